#pragma once
// Soft bodies in a frame: each drawn as its boundary surface over the nodes where the engine moved
// them, smooth shaded; the overlay shows the constitutive model, the integrator, the stable
// explicit step and the energies (issue 10).
#include "render/frame_data.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

void addSoftView(const World& world, render::FrameData& frame);

}  // namespace rbsim::app
