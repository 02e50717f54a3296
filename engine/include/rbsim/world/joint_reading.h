#pragma once
// What a joint does now (issue 39; Box2D v3's b2RevoluteJoint_GetAngle, b2PrismaticJoint_GetTranslation,
// GetConstraintForce and GetConstraintTorque, PyBullet's getJointState): the hinge angle and speed,
// the slider's translation and speed, the ball's swing and twist, where its two anchors are, and
// the force and torque the joint puts on body A, from the impulses of the last substep.
#include <cstddef>

#include "rbsim/math/types.h"

namespace rbsim {

class World;

struct JointReading {
  // Hinge: the angle of A relative to B (or the world) about the axis, from where it was added
  // [rad], in (-pi, pi] (hingeAngle), and A's turning relative to B about the axis [rad/s]. NaN
  // for a ball joint, which has no axis.
  double angle = 0.0;
  double speed = 0.0;
  // Prismatic: A's anchor from B's along the axis, 0 where it was added [m], and its rate [m/s].
  // NaN for the other types.
  double translation = 0.0;
  double translationSpeed = 0.0;
  // Ball: the swing (the angle between B's copy of the axis and A's, in [0, pi]) and the twist
  // about it (hingeAngle) [rad], what the cone and twist limits hold. NaN for the other types.
  double swing = 0.0;
  double twist = 0.0;
  Vec3 axis = Vec3::UnitZ();      // the axis, world frame, as B carries it
  Vec3 anchorA = Vec3::Zero();    // A's copy of the pivot, world frame [m]
  Vec3 anchorB = Vec3::Zero();    // B's (or the world's) [m]; |anchorA - anchorB| is the joint's drift
  // On body A, world frame: the joint's last substep impulses over the substep h = dt / substeps
  // (Box2D v3's constraint force and torque). The torque is the constraint's own (keeping the axes
  // aligned, the motor, limits, spring and friction), about A's anchor; B feels the opposite [N], [N m]. h is
  // taken from the settings now: read before changing dt or substeps (World::setSettings).
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
};

// Throws std::invalid_argument for an index beyond World::joints().
JointReading readJoint(const World& world, std::size_t joint);

}  // namespace rbsim
