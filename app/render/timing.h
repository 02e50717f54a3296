#pragma once
// Per-frame cost of the output path, averaged, so the app can print
// "ms per frame: render X, copy Y, encode Z (background)".
#include <mutex>
#include <string>

namespace rbsim::render {

struct RenderTiming {
  long frames = 0;
  double renderMs = 0.0;  // GL draw of scene and overlay, including glFinish
  double copyMs = 0.0;    // flipping the GL buffer into the top-down RGBA image
};

struct SinkTiming {
  long frames = 0;
  double encodeMs = 0.0;   // pngMs + videoMs: background work per frame
  double pngMs = 0.0;      // stb PNG encode + write of one frame, per worker
  double videoMs = 0.0;    // handing one frame to ffmpeg (waits while it encodes)
  double blockedMs = 0.0;  // time submit() waited on a full queue (0 when background keeps up)
};

// "ms per frame: render 12.3, copy 0.8, encode 20.1 (background)"
std::string formatTiming(const RenderTiming& render, const SinkTiming& sink);

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
