#include "run/frame_steps.h"

#include <cmath>

namespace rbsim::app {

std::uint64_t stepOfFrame(std::uint64_t frame, double fps, double dt) {
  // std::round rounds halves away from zero, as llround did; the saturation keeps the cast defined.
  const double step = std::round(static_cast<double>(frame) / (fps * dt));
  return step >= static_cast<double>(kHugeCount) ? kHugeCount : static_cast<std::uint64_t>(step);
}

std::uint64_t firstFrameShowing(std::uint64_t step, double fps, double dt) {
  if (step == 0) return 0;
  // round(k / r) >= step  <=>  k >= (step - 1/2) r; the estimate is off by rounding only, so the
  // two loops below move it a frame or two at most.
  const double estimate = std::ceil((static_cast<double>(step) - 0.5) * fps * dt);
  if (!(estimate < static_cast<double>(kHugeCount))) return kHugeCount;
  std::uint64_t frame = estimate > 0.0 ? static_cast<std::uint64_t>(estimate) : 0;
  while (frame > 0 && stepOfFrame(frame - 1, fps, dt) >= step) --frame;
  while (frame < kHugeCount && stepOfFrame(frame, fps, dt) < step) ++frame;
  return frame;
}

std::uint64_t frameCount(std::uint64_t steps, double fps, double dt) {
  return steps >= kHugeCount ? kHugeCount : firstFrameShowing(steps + 1, fps, dt);
}

std::uint64_t frameCount(const Scene& scene) {
  return frameCount(scene.stepCount(), scene.view.fps, scene.settings.timeStep);
}

}  // namespace rbsim::app
