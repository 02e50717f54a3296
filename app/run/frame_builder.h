#pragma once
// World + view description -> the renderer's FrameData: world vertices as the engine computed
// them, body axes, active force arrows, and the overlay's variable table (seed 004 optional
// "visualisation of variables").
#include <string>

#include "render/frame_data.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

render::Camera sceneCamera(const ViewDesc& view);

// `selectedBodyRows` false leaves the selected body's variables out of the overlay's rows (a
// compared phase, compare_view.h, shows its own rows of every world instead).
render::FrameData buildFrame(const World& world, const Scene& scene, const std::string& demoTitle,
                             bool selectedBodyRows = true);

// "+1.0000 -2.0000 +0.5000 m": the overlay's format of a vector.
std::string formatVec(const Vec3& v, const char* unit);
// "0.25 J": the overlay's format of a number.
std::string formatNumber(double value, const char* unit);

}  // namespace rbsim::app
