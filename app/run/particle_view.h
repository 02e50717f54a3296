#pragma once
// The World's particle systems as the renderer sees them: a sprite batch per system (colour,
// opacity and size following each particle's age as the scene's ParticleLook says), a shaded
// surface per cloth, and a line per system in the overlay.
#include "render/frame_data.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

void addParticleView(const World& world, const Scene& scene, render::FrameData& frame);

}  // namespace rbsim::app
