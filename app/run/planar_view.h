#pragma once
// The 2D world in a frame: each polygon drawn as a prism of the scene's planar depth in the xy
// plane, and its state (x, theta, omega, L = I omega) in the overlay (seed 002 section 2).
#include "render/frame_data.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

void addPlanarView(const World& world, const Scene& scene, render::FrameData& frame);

}  // namespace rbsim::app
