#pragma once
// Progress of a long render on stderr: "demo 3/6 broadphase  frames 1234/7440 (16.6%)
// 21.3 fps  elapsed 0:58  ETA 4:52" (a run without images counts "steps" at "steps/s"). Rewritten in place (\r) on a terminal; one line every few
// seconds otherwise (a log file or CI would fill up with carriage returns).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace rbsim::app {

struct ProgressState {
  std::size_t item = 0;   // 1-based: which demo (or phase) is running
  std::size_t items = 0;  // how many in all
  std::string name;       // the demo's (or the phase's scene file's) name
  std::uint64_t done = 0;   // frames (or steps) finished so far, every demo and card counted
  std::uint64_t total = 0;  // frames (or steps) planned in all
  double elapsedSeconds = 0.0;
  std::string kind = "demo";    // what an item is: "demo" in the reel, "phase" in one run
  std::string unit = "frames";  // what done and total count: "frames", or "steps" without images
};

// Seconds as a clock: "0:07", "12:34", "1:02:03"; "--:--" when not finite or negative (no
// estimate yet). Rounded to whole seconds.
std::string formatClock(double seconds);

// The progress line; the ETA assumes the mean frame rate so far holds for the frames left.
std::string progressLine(const ProgressState& state);

class ProgressMeter {
 public:
  // Writes to `out` unless `quiet`; `inPlace` rewrites one line with \r (a terminal).
  ProgressMeter(std::FILE* out, bool inPlace, bool quiet);
  ~ProgressMeter() { finish(); }  // an error message after a failed run starts on its own line
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // Reports the state if enough time has passed since the last report (or since the start: a
  // first frame says nothing about the rate), or when `force`; cheap otherwise.
  void update(const ProgressState& state, bool force = false);
  // Ends the in-place line so later output starts on a fresh one.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::FILE* out_;
  bool inPlace_;
  bool quiet_;
  bool wrote_ = false;
  Clock::time_point last_ = Clock::now();
  std::size_t lastWidth_ = 0;
};

// Whether `stream` is a terminal (progress is then rewritten in place).
bool isTerminal(std::FILE* stream);

}  // namespace rbsim::app
