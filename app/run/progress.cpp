#include "run/progress.h"

#include <cmath>
#include <unistd.h>

namespace rbsim::app {

namespace {

// A terminal redraws in place a few times a second: smooth, without flooding a slow terminal.
constexpr double kTerminalIntervalSeconds = 0.25;
// A log gets one line every 5 s: enough to see it move, few enough to read.
constexpr double kLogIntervalSeconds = 5.0;

}  // namespace

std::string formatClock(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
  const auto whole = static_cast<long long>(std::llround(seconds));
  const long long h = whole / 3600, m = whole / 60 % 60, s = whole % 60;
  char buffer[32];
  if (h > 0) {
    std::snprintf(buffer, sizeof buffer, "%lld:%02lld:%02lld", h, m, s);
  } else {
    std::snprintf(buffer, sizeof buffer, "%lld:%02lld", m, s);
  }
  return buffer;
}

std::string progressLine(const ProgressState& state) {
  const double rate = state.elapsedSeconds > 0.0 ? static_cast<double>(state.done) / state.elapsedSeconds : 0.0;
  const std::uint64_t left = state.total > state.done ? state.total - state.done : 0;
  const double eta = left == 0 ? 0.0 : rate > 0.0 ? static_cast<double>(left) / rate : -1.0;
  const double percent = state.total > 0 ? 100.0 * static_cast<double>(state.done) / static_cast<double>(state.total) : 100.0;
  char buffer[256];
  const std::string rateUnit = state.unit == "frames" ? "fps" : state.unit + "/s";
  std::snprintf(buffer, sizeof buffer, "%s %zu/%zu %s  %s %llu/%llu (%.1f%%)  %.1f %s  elapsed %s  ETA %s",
                state.kind.c_str(), state.item, state.items, state.name.c_str(), state.unit.c_str(),
                static_cast<unsigned long long>(state.done),
                static_cast<unsigned long long>(state.total), percent, rate, rateUnit.c_str(), formatClock(state.elapsedSeconds).c_str(),
                formatClock(eta).c_str());
  return buffer;
}

ProgressMeter::ProgressMeter(std::FILE* out, bool inPlace, bool quiet) : out_(out), inPlace_(inPlace), quiet_(quiet) {}

void ProgressMeter::update(const ProgressState& state, bool force) {
  if (quiet_) return;
  const Clock::time_point now = Clock::now();
  const double interval = inPlace_ ? kTerminalIntervalSeconds : kLogIntervalSeconds;
  if (!force && std::chrono::duration<double>(now - last_).count() < interval) return;
  const std::string line = progressLine(state);
  if (inPlace_) {
    // Pad with spaces over the tail of a longer previous line (a longer demo name).
    const std::size_t pad = lastWidth_ > line.size() ? lastWidth_ - line.size() : 0;
    std::fprintf(out_, "\r%s%*s", line.c_str(), static_cast<int>(pad), "");
    lastWidth_ = line.size();
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
  wrote_ = true;
  last_ = now;
}

void ProgressMeter::finish() {
  if (quiet_ || !wrote_ || !inPlace_) return;
  std::fprintf(out_, "\n");
  std::fflush(out_);
  lastWidth_ = 0;
  wrote_ = false;
}

bool isTerminal(std::FILE* stream) { return ::isatty(::fileno(stream)) == 1; }

}  // namespace rbsim::app
