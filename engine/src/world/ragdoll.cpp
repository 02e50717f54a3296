// The ragdoll preset (world/ragdoll.h): bones as capsules along body y, standing; joints from
// child to parent with the ranges of a person's (a shoulder's cone, an elbow's and a knee's
// hinge). Layout after Box3D's shared/human.c; segment masses as fractions of the whole after
// Winter, "Biomechanics and Motor Control of Human Movement" (2009), table 4.1, rounded so that
// they sum to 1.
#include "rbsim/world/ragdoll.h"

#include <cmath>
#include <memory>

#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/shapes/shape.h"
#include "rbsim/world/joint_changes.h"
#include "rbsim/world/world.h"

namespace rbsim {

namespace {

// The capsules drawn with as many segments and rings as a scene's (scene/body_parser.cpp).
constexpr int kCapsuleSegments = 24;  // [1]
constexpr int kCapsuleRings = 12;     // [1]

struct BoneShape {
  const char* name;
  double x, y;          // centre at scale 1, standing, feet at the origin [m]
  double length;        // between the cap centres [m]
  double radius;        // [m]
  double massFraction;  // [1]
};

// Index by Bone. Arms hang at the sides (x = +-0.22 m), legs at x = +-0.1 m.
constexpr BoneShape kBones[kBoneCount] = {
    {"pelvis", 0.0, 0.98, 0.10, 0.10, 0.142},
    {"torso", 0.0, 1.25, 0.25, 0.13, 0.355},
    {"head", 0.0, 1.67, 0.06, 0.10, 0.081},
    {"upper_arm_left", 0.22, 1.30, 0.20, 0.045, 0.028},
    {"lower_arm_left", 0.22, 1.00, 0.20, 0.040, 0.022},
    {"upper_arm_right", -0.22, 1.30, 0.20, 0.045, 0.028},
    {"lower_arm_right", -0.22, 1.00, 0.20, 0.040, 0.022},
    {"upper_leg_left", 0.10, 0.71, 0.34, 0.065, 0.100},
    {"lower_leg_left", 0.10, 0.25, 0.34, 0.055, 0.061},
    {"upper_leg_right", -0.10, 0.71, 0.34, 0.065, 0.100},
    {"lower_leg_right", -0.10, 0.25, 0.34, 0.055, 0.061},
};

// Limits in radians: a ball's cone half-angle and twist range about its axis (from the parent
// along the child), a hinge's range about +x (positive turns a hanging bone's end backward, -z).
struct JointShape {
  Bone child, parent;
  double x, y;       // anchor at scale 1 [m]
  bool ball;
  double axisY;      // the ball's axis, +1 up or -1 down along y; a hinge's axis is x
  double cone;       // ball [rad]
  double lower, upper;  // twist (ball) or angle (hinge) [rad]
};

constexpr JointShape kJoints[kBoneCount - 1] = {
    {Bone::Torso, Bone::Pelvis, 0.0, 1.08, true, 1.0, 0.5, -0.4, 0.4},            // waist
    {Bone::Head, Bone::Torso, 0.0, 1.52, true, 1.0, 0.6, -0.8, 0.8},              // neck
    {Bone::UpperArmLeft, Bone::Torso, 0.22, 1.45, true, -1.0, 1.6, -0.6, 0.6},    // shoulders
    {Bone::UpperArmRight, Bone::Torso, -0.22, 1.45, true, -1.0, 1.6, -0.6, 0.6},
    {Bone::LowerArmLeft, Bone::UpperArmLeft, 0.22, 1.15, false, 0.0, 0.0, -2.5, 0.0},  // elbows bend forward
    {Bone::LowerArmRight, Bone::UpperArmRight, -0.22, 1.15, false, 0.0, 0.0, -2.5, 0.0},
    {Bone::UpperLegLeft, Bone::Pelvis, 0.10, 0.90, true, -1.0, 1.0, -0.4, 0.4},   // hips
    {Bone::UpperLegRight, Bone::Pelvis, -0.10, 0.90, true, -1.0, 1.0, -0.4, 0.4},
    {Bone::LowerLegLeft, Bone::UpperLegLeft, 0.10, 0.50, false, 0.0, 0.0, 0.0, 2.5},   // knees bend backward
    {Bone::LowerLegRight, Bone::UpperLegRight, -0.10, 0.50, false, 0.0, 0.0, 0.0, 2.5},
};

}  // namespace

std::size_t ragdollVertexCount() {
  // The capsules' vertex count depends on their segments and rings alone, not on their size.
  const std::size_t perBone = makeCapsule(1.0, 1.0, kCapsuleSegments, kCapsuleRings).vertices.size();
  return kBoneCount * perBone;
}

const char* boneName(Bone bone) { return kBones[static_cast<std::size_t>(bone)].name; }

Ragdoll addRagdoll(World& world, const RagdollDef& def) {
  Ragdoll ragdoll;
  const double s = def.scale;
  const auto place = [&](double x, double y) { return Vec3(def.position + def.orientation * Vec3(s * x, s * y, 0.0)); };
  for (std::size_t i = 0; i < kBoneCount; ++i) {
    const BoneShape& bone = kBones[i];
    BodyDef body;
    body.name = def.name + "_" + bone.name;
    body.shape = Shape::capsule(s * bone.radius, 0.5 * s * bone.length);
    body.mesh = std::make_shared<const Mesh>(makeCapsule(s * bone.radius, s * bone.length, kCapsuleSegments, kCapsuleRings));
    body.mass = def.mass * bone.massFraction;
    body.inertiaBody = roundOrBoxInertia(*body.shape, body.mass);
    body.position = place(bone.x, bone.y);
    body.orientation = def.orientation;
    body.velocity = def.velocity;
    ragdoll.bodies[i] = world.addBody(body);
  }
  // Friction and spring torques scale with mass times length (s^3 s = s^4), as a figure's weight
  // torques do, so a larger figure goes as limp as a smaller one.
  const double torqueScale = std::pow(s, 4);
  for (std::size_t j = 0; j < kBoneCount - 1; ++j) {
    const JointShape& shape = kJoints[j];
    JointDef joint;
    joint.name = def.name + "_" + kBones[static_cast<std::size_t>(shape.child)].name;
    joint.bodyA = ragdoll.bodies[static_cast<std::size_t>(shape.child)];
    joint.bodyB = ragdoll.bodies[static_cast<std::size_t>(shape.parent)];
    joint.anchor = place(shape.x, shape.y);
    joint.type = shape.ball ? JointDef::Type::Ball : JointDef::Type::Hinge;
    joint.axis = def.orientation * (shape.ball ? Vec3(0.0, shape.axisY, 0.0) : Vec3::UnitX());
    joint.limits = true;
    joint.lowerAngle = shape.lower;
    joint.upperAngle = shape.upper;
    joint.coneLimit = shape.ball;
    joint.coneAngle = shape.cone;
    joint.friction = def.jointFriction * torqueScale;
    joint.spring = def.jointHertz > 0.0;
    joint.springHertz = def.jointHertz;
    joint.springDampingRatio = def.jointDampingRatio;
    ragdoll.joints[j] = indexOf(world, world.addJoint(joint));
  }
  return ragdoll;
}

}  // namespace rbsim
