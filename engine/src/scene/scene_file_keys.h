#pragma once
// The top-level keys of a scene file (rbsim/scene/scene_keys.h), each block's table below it:
// what parseScene reads, and what docs/scene.schema.json is generated from.
#include "rbsim/scene/scene_keys.h"
#include "rbsim/scene/world_keys.h"
#include "scene/body_keys.h"
#include "scene/joint_keys.h"
#include "scene/spawn_keys.h"

namespace rbsim::scene_detail {

inline constexpr SceneKey kSceneKeyTable[] = {
    key("$schema", KeyType::String, "the JSON Schema an editor checks the file against (rbsim ignores it)"),
    key("title", KeyType::String, "text shown in the overlay (default: the file's name)"),
    key("world", KeyType::Object, "the physics").of(kWorldKeys),
    key("view", KeyType::Object, "how the scene is shown").of(kViewKeys),
    key("bodies", KeyType::ObjectArray, "the rigid bodies").of(kBodyKeys),
    key("planes", KeyType::ObjectArray, "infinite static planes").of(kPlaneKeys),
    key("spawn", KeyType::ObjectArray, "blocks that make many bodies from one template").of(kSpawnKeys),
    key("kill_volume", KeyType::Object, "bodies leaving this box are removed").of(kRegionKeys),
    key("particles", KeyType::ObjectArray, "particle systems (docs/scene-format.md, \"Particle systems\")"),
    key("soft_bodies", KeyType::ObjectArray, "FEM soft bodies (docs/scene-format.md, \"Soft bodies\")"),
    key("planar", KeyType::Object, "a 2D rigid-body world (docs/scene-format.md, \"2D rigid bodies\")"),
    key("joints", KeyType::ObjectArray, "joints between bodies").of(kJointKeys).byType(kJointVariants),
    key("ragdolls", KeyType::ObjectArray, "eleven-bone ragdolls").of(kRagdollKeys),
};
// The keys of a scene file's top level.
inline constexpr KeyTable kSceneKeys{kSceneKeyTable, "an rbsim scene"};

}  // namespace rbsim::scene_detail
