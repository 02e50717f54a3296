#pragma once
// Scene-file parsing of the "joints" array into JointDef (keys in docs/scene-format.md,
// "Joints"). Internal to scene/; bodies and the world block must be parsed first.
#include <string>
#include <unordered_map>
#include <vector>

#include "rbsim/dynamics/joint.h"
#include "rbsim/dynamics/joint_ranges.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"
#include "scene/joint_keys.h"

namespace rbsim::scene_detail {

// What a joint needs to know of the bodies it may name: per body its name and whether it is
// dynamic (body_a must be).
struct JointBodies {
  std::vector<std::string> names;
  std::vector<char> dynamic;
  std::vector<BodyId> ids;  // what the joint names them by: sceneBodyId(i) in a scene, the World's own ids in a World
  // A scene's ragdolls, whose bones are made with the World, after its joints: a joint that names
  // one is told so (their names are the ragdoll's, "_", and the bone's).
  std::vector<std::string> ragdolls;
  // The first body of each name, filled on the first look-up: a joint finds its bodies by hashing,
  // not by scanning every name (a 100 x 100 joint grid has 19701 joints and 10000 bodies).
  mutable std::unordered_map<std::string, std::size_t> first;
};

// Joints a scene may hold at most. Loading is linear: 100,000 joints (a chain of 100,000 balls)
// parse and enter a World in 0.39 s on our 2-core machine, so the limit is a few seconds; a 64 MB
// scene file could hold 1.6 million of the shortest ({"type":"ball","body_a":"a","body_b":"b"}).
inline constexpr std::size_t kMaxJoints = 1'000'000;

// A joint's "motor" ({"speed", "max_torque"} or a slider's {"speed", "max_force"}) into def, and
// its "limits" (a ball's "twist"): each checked as setJointMotor and setJointLimits check
// it (dynamics/joint_ranges.h). A motor's key left out keeps def's value when def has a motor
// already (World.set_joint), and is missing otherwise.
void parseMotor(const JsonObject& j, JointDef& def);
void parseLimits(const JsonObject& j, JointDef& def);

// One entry of "joints"; `solver` refuses joints under PGS, which does not solve them.
JointDef parseJoint(const JsonObject& j, const JointBodies& bodies, const Settings& settings);
// "joints": [{...}, ...] into scene.joints.
void parseJoints(const JsonObject& root, Scene& scene);

}  // namespace rbsim::scene_detail
