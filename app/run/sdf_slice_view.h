#pragma once
// view.sdf_slice (issue 55, "Seed 000's signed distance grid"): one layer of a body's signed
// distance grid beside the scene, as the grid was built (seed 000 "Constructing Signed Distance
// Functions"): phi as a diverging colour map with its zero contour, and which stage set each
// value (narrow band or fast marching) in the colour of its flood-fill region, each with its
// legend; in the 3D view, the layer's outline and its zero contour on the body.
#include "render/frame_data.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// The maps' column starts at this fraction of the image width; the scene's camera frames the body
// left of it (assets/scenes/sdf_slice.json).
inline constexpr float kSliceColumnLeft = 0.38f;  // [1]

// Adds the maps, their notes and the 3D lines to `frame` when scene.view.sdfSlice is set.
void addSdfSliceView(const World& world, const Scene& scene, render::FrameData& frame);

}  // namespace rbsim::app
