#pragma once
// What the collision demos show (demos 3 and 4): AABBs (red when in an overlapping pair),
// contact points and normals, the closest points and distance of the selected body to its
// nearest neighbour, ghosts where continuous collision stopped a body, and overlay rows with
// the pair counts of sweep and prune against brute force and their timings.
#include "render/frame_data.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

void addCollisionView(const World& world, const Scene& scene, render::FrameData& frame);

}  // namespace rbsim::app
