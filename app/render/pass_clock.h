#pragma once
// Where a frame's rasterising time goes, pass by pass. llvmpipe bins every draw and rasterises
// only at a flush, so the time of a pass is measurable only by finishing after it: on one frame
// in kPassSampleEvery, the renderer calls glFinish after each pass and charges the time since the
// previous mark to that pass. Those frames cost a little more (every flush stores and reloads the
// tiles), which is why the others run unmeasured.
#include <array>
#include <chrono>

namespace rbsim::render {

enum class RenderPass {
  Upload,      // scene geometry built on the CPU and uploaded (bodies, lines, instances)
  Background,  // sky and ground copied in (and drawn first, when the camera moved)
  Bodies,      // opaque bodies (flat shaded; instanced where they share a mesh)
  Shadows,     // planar shadows onto the ground
  Edges,      // body outlines and the selection highlight
  Marks,      // particles, debug lines, axes, force arrows, ghosts
  Overlay,    // the Dear ImGui panel and captions
  Count
};

constexpr int kRenderPassCount = static_cast<int>(RenderPass::Count);
constexpr long kPassSampleEvery = 8;  // frames between two measured frames

// The passes' names as printSummary prints them.
constexpr std::array<const char*, kRenderPassCount> kRenderPassNames = {
    "upload", "background", "bodies", "shadows", "edges", "marks", "overlay"};

// Accumulates per-pass milliseconds over the measured frames. mark() is called by the renderer;
// `finish` is the glFinish it runs first (kept out of this header so it stays GL-free).
class PassClock {
 public:
  using Clock = std::chrono::steady_clock;

  void begin() { last_ = Clock::now(); }
  template <typename Finish>
  void mark(RenderPass pass, Finish finish) {
    finish();
    const Clock::time_point now = Clock::now();
    totalMs_[static_cast<int>(pass)] += std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
  }
  void endFrame() { ++frames_; }

  long frames() const { return frames_; }
  // Mean milliseconds of each pass over the measured frames (zeros before the first).
  std::array<double, kRenderPassCount> meanMs() const {
    std::array<double, kRenderPassCount> mean{};
    if (frames_ == 0) return mean;
    for (int k = 0; k < kRenderPassCount; ++k) mean[k] = totalMs_[k] / static_cast<double>(frames_);
    return mean;
  }

 private:
  Clock::time_point last_{};
  std::array<double, kRenderPassCount> totalMs_{};
  long frames_ = 0;
};

}  // namespace rbsim::render
