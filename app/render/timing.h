#pragma once
// Per-frame cost of the output path, averaged, so the app can say where a frame's time went.
#include <array>
#include <mutex>

#include "pass_clock.h"

namespace rbsim::render {

struct RenderTiming {
  long frames = 0;
  double renderMs = 0.0;    // issuing scene and overlay (begin) plus waiting for them (finish)
  double readbackMs = 0.0;  // the finished framebuffer read into the top-down RGBA image
  long passFrames = 0;      // frames measured pass by pass (one in kPassSampleEvery)
  std::array<double, kRenderPassCount> passMs{};  // mean ms of each pass over those frames
};

struct SinkTiming {
  long frames = 0;
  double pngMs = 0.0;      // deflate + write of one PNG, on a worker thread
  double videoMs = 0.0;    // pipe write of one frame to ffmpeg (waits while ffmpeg encodes)
  double blockedMs = 0.0;  // time submit() waited on a full queue (0 when background keeps up)
};

// A thread-safe running mean of durations in milliseconds.
class MeanMs {
 public:
  void add(double ms) {
    std::lock_guard<std::mutex> lock(mutex_);
    sum_ += ms;
    ++count_;
  }
  double mean() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return count_ > 0 ? sum_ / static_cast<double>(count_) : 0.0;
  }

 private:
  mutable std::mutex mutex_;
  double sum_ = 0.0;
  long count_ = 0;
};

}  // namespace rbsim::render
