#include "run/output_budget.h"

#include <cstdio>

#include "rbsim/io/input_error.h"

namespace rbsim::app {

namespace {

constexpr double kSecondsPerHour = 3600.0;

std::string hoursOfVideo(std::uint64_t frames, int fps) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3g h of video at %d fps", static_cast<double>(frames) / fps / kSecondsPerHour,
                fps);
  return buffer;
}

}  // namespace

std::string formatBytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  std::size_t unit = 0;
  while (bytes >= 1000.0 && unit + 1 < sizeof units / sizeof units[0]) {
    bytes /= 1000.0;
    ++unit;
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3g %s", bytes, units[unit]);
  return buffer;
}

void checkOutputBudget(const std::string& file, const std::string& what, std::uint64_t frames, int width, int height,
                       int fps, const std::string& framesDir, int pngLevel) {
  if (frames > kMaxRenderedFrames) {
    throw InputError(file, "world.duration",
                     what + " renders " + std::to_string(frames) + " frames (" + hoursOfVideo(frames, fps) +
                         "); the limit is " + std::to_string(kMaxRenderedFrames) + " frames (" +
                         hoursOfVideo(kMaxRenderedFrames, fps) +
                         "): shorten world.duration, lower view.fps, or simulate only with --no-render");
  }
  if (framesDir.empty()) return;
  const double perPixel = pngLevel == 0 ? kStoredPngBytesPerPixel : kDeflatedPngBytesPerPixel;
  const double bytes = static_cast<double>(frames) * width * height * perPixel;
  if (bytes > kMaxFramesFolderBytes) {
    char perPixelText[32];
    std::snprintf(perPixelText, sizeof perPixelText, "%.2g", perPixel);
    throw InputError(framesDir, "--frames",
                     std::to_string(frames) + " PNG frames of " + std::to_string(width) + "x" + std::to_string(height) +
                         " at --png-level " + std::to_string(pngLevel) + " need ~" + formatBytes(bytes) + " (~" +
                         perPixelText + " bytes a pixel); the limit is " + formatBytes(kMaxFramesFolderBytes) +
                         ": fewer frames, a smaller view.size, or no --frames");
  }
}

void checkTraceBudget(const std::string& tracePath, double rows, const std::string& how) {
  const double bytes = rows * kMinTraceBytesPerRow;
  if (bytes <= kMaxTraceBytes) return;
  char rowsText[32];
  std::snprintf(rowsText, sizeof rowsText, "%.3g", rows);
  throw InputError(tracePath, "--trace",
                   std::string(rowsText) + " rows (" + how + ") need at least ~" + formatBytes(bytes) + " (~" +
                       std::to_string(static_cast<int>(kMinTraceBytesPerRow)) + " bytes a row); the limit is " +
                       formatBytes(kMaxTraceBytes) + ": trace every K-th step (--trace-every K) or run fewer steps");
}

}  // namespace rbsim::app
