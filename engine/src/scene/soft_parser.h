#pragma once
// Scene-file parsing of "soft_bodies" blocks into SoftBodyDef (keys in docs/scene-format.md,
// "Soft bodies (FEM) and 2D rigid bodies"). Internal to scene/.
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim::scene_detail {

void parseSoftBodies(const JsonObject& root, Scene& scene);

}  // namespace rbsim::scene_detail
