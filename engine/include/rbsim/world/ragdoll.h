#pragma once
// A ragdoll preset (issue 40): eleven capsules (pelvis, torso, head, upper and lower arms, upper
// and lower legs) joined by ball joints with cone and twist limits at the waist, neck, shoulders
// and hips, and hinges with limits at the elbows and knees, each with joint friction and a soft
// spring toward the standing pose. The layout of Box3D's shared/human.c (read, not copied): a
// standing person, feet at `position`, facing +z, sized by `scale`.
#include <array>
#include <cstddef>
#include <string>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

class World;

struct RagdollDef {
  std::string name = "ragdoll";       // bodies are named name + "_" + bone ("ragdoll_pelvis")
  Vec3 position = Vec3::Zero();       // between the feet, world frame [m]
  Quat orientation = Quat::Identity();  // of the whole figure about `position`
  Vec3 velocity = Vec3::Zero();       // of every bone [m/s]
  double scale = 1.0;                 // 1: 1.8 m tall [1]
  double mass = 70.0;                 // the whole figure [kg], shared as a person's segments are
  double jointFriction = 1.0;         // each joint's friction torque at scale 1 [N m]: slows a limb's slump, holds no pose
  double jointHertz = 1.0;            // the springs toward the standing pose [Hz]; 0: none
  double jointDampingRatio = 0.5;     // [1]
};

enum class Bone : std::size_t {
  Pelvis, Torso, Head, UpperArmLeft, LowerArmLeft, UpperArmRight, LowerArmRight,
  UpperLegLeft, LowerLegLeft, UpperLegRight, LowerLegRight, Count
};
inline constexpr std::size_t kBoneCount = static_cast<std::size_t>(Bone::Count);

struct Ragdoll {
  std::array<BodyId, kBoneCount> bodies{};       // indexed by Bone
  std::array<std::size_t, kBoneCount - 1> joints{};  // World::joints() rows: waist, neck, shoulders, elbows, hips, knees
};

// "pelvis", "torso", ..., "lower_leg_right": what a bone's body is named after.
const char* boneName(Bone bone);

// The vertices of one figure's eleven capsule meshes, which a spawned figure copies.
std::size_t ragdollVertexCount();

// Adds the figure's bodies and joints to `world` (which must use the soft-step solver).
Ragdoll addRagdoll(World& world, const RagdollDef& def);

}  // namespace rbsim
