#pragma once
// Which step each frame of a scene shows, and how many frames a run renders: arithmetic on
// counts, fps and dt, apart from the runner (runner.h), so the scene loader (phase.h) and the
// Python module's physics-only build use it without the renderer.
#include <cstdint>

#include "rbsim/scene/scene.h"

namespace rbsim::app {

// Frame k of a scene shows the state at the step nearest to k / fps. When dt does not divide
// 1/fps the frames' times jitter by at most dt/2 but never drift; none is dropped, and a step is
// shown twice only when dt > 1/fps. Saturates at kHugeCount instead of overflowing.
std::uint64_t stepOfFrame(std::uint64_t frame, double fps, double dt);

// Counts past this are "too many" (no run gets near it); it is exact in a double, so frame and
// step arithmetic never overflows a 64-bit integer on the way to a budget check.
inline constexpr std::uint64_t kHugeCount = std::uint64_t{1} << 62;

// The first frame whose step (stepOfFrame) is `step` or later, computed directly: counting frame
// by frame would take ~1e11 iterations for 1e9 steps shown at 240 fps with a large dt.
std::uint64_t firstFrameShowing(std::uint64_t step, double fps, double dt);

// How many frames runPhases renders for a scene of `steps` steps: every k with
// stepOfFrame(k) <= steps (frame 0 is the initial state), so at least 1.
std::uint64_t frameCount(std::uint64_t steps, double fps, double dt);
std::uint64_t frameCount(const Scene& scene);

}  // namespace rbsim::app
