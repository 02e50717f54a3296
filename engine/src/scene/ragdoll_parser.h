#pragma once
// Scene-file parsing of "ragdolls": presets of eleven bodies and ten joints (world/ragdoll.h),
// added by buildWorld after the bodies. Internal to scene/.
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/ragdoll.h"

#include "scene/spawn_keys.h"

namespace rbsim::scene_detail {

// "ragdolls": [{"name", "position", "orientation", "velocity", "scale", "mass", "joint_friction",
// "joint_hertz", "joint_damping_ratio"}, ...]: each a RagdollDef in scene.ragdolls.
void parseRagdolls(const JsonObject& root, Scene& scene);

void parseRagdollFigure(const JsonObject& r, RagdollDef& def);

}  // namespace rbsim::scene_detail
