#pragma once
// World + view description -> the renderer's FrameData: world vertices as the engine computed
// them, body axes, active force arrows, and the overlay's variable table (seed 004 optional
// "visualisation of variables").
#include <string>

#include "render/frame_data.h"
#include "scene/scene.h"
#include "world/world.h"

namespace rbsim::app {

render::Camera sceneCamera(const ViewDesc& view);

render::FrameData buildFrame(const World& world, const Scene& scene, const std::string& demoTitle);

}  // namespace rbsim::app
