#include "rbsim/world/joint_reading.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "rbsim/world/world.h"

namespace rbsim {

JointReading readJoint(const World& world, std::size_t index) {
  const std::vector<Joint>& joints = world.joints();
  if (index >= joints.size()) {
    throw std::invalid_argument("readJoint: joint " + std::to_string(index) + " of " + std::to_string(joints.size()));
  }
  const Joint& joint = joints[index];
  const RigidBody& a = world.body(joint.def.bodyA);
  const bool onWorld = joint.def.bodyB == kWorldAnchor;
  const RigidBody* b = onWorld ? nullptr : &world.body(joint.def.bodyB);
  const Quat baseOrientation = onWorld ? Quat::Identity() : b->orientation();
  const Vec3 baseOmega = onWorld ? Vec3::Zero() : b->angularVelocity();

  JointReading r;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.axis = (baseOrientation * joint.localAxisBase).normalized();
  r.anchorA = a.position() + a.rotation() * joint.localAnchorMoving;
  r.anchorB = onWorld ? joint.localAnchorBase : Vec3(b->position() + b->rotation() * joint.localAnchorBase);
  r.angle = r.speed = r.translation = r.translationSpeed = r.swing = r.twist = nan;
  const JointDef::Type type = joint.def.type;
  if (type == JointDef::Type::Hinge) {
    r.angle = hingeAngle(joint, baseOrientation, a.orientation());
    r.speed = r.axis.dot(a.angularVelocity() - baseOmega);
  } else if (type == JointDef::Type::Ball) {
    r.swing = swingAngle(joint, baseOrientation, a.orientation());
    r.twist = hingeAngle(joint, baseOrientation, a.orientation());
  } else if (type == JointDef::Type::Prismatic) {
    // Box2D v3's b2PrismaticJoint_GetSpeed: the base's axis turns with it, so its own motion at
    // A's anchor is subtracted.
    const Vec3 d = r.anchorA - r.anchorB;
    const auto velocityAt = [](const RigidBody& body, const Vec3& p) {
      return Vec3(body.velocity() + body.angularVelocity().cross(p - body.position()));
    };
    const Vec3 baseVelocity = onWorld ? Vec3::Zero() : velocityAt(*b, r.anchorA);
    r.translation = r.axis.dot(d);
    r.translationSpeed = r.axis.dot(velocityAt(a, r.anchorA) - baseVelocity);
  }
  // soft_step_joints.cpp applies +impulse to A (its "moving" side) and keeps each substep's; a
  // slider's axial impulses are linear, the others' angular.
  const Settings& s = world.settings();
  const double inverseH = static_cast<double>(s.substeps) / s.timeStep;
  const double axial = joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
  const Vec3 extra = joint.springImpulse + joint.frictionImpulse;
  Vec3 linear = joint.linearImpulse, angular = joint.angularImpulse;
  if (type == JointDef::Type::Prismatic) {
    linear += axial * r.axis + extra;
  } else if (type == JointDef::Type::Hinge) {
    angular += axial * r.axis + extra;
  } else if (type == JointDef::Type::Ball) {
    // The twist and cone act about axes of the step (soft_step_joints.cpp); their approximation
    // here is A's axis for the twist, and the swing direction for the cone.
    const Vec3 twistAxis = (a.orientation() * joint.localAxisMoving).normalized();
    const Vec3 normal = r.axis.cross(twistAxis);
    const Vec3 swingAxis = normal.norm() > 0.0 ? Vec3(normal.normalized()) : Vec3::Zero();
    angular += extra + (joint.lowerImpulse - joint.upperImpulse) * twistAxis - joint.swingImpulse * swingAxis;
  }
  r.force = linear * inverseH;
  r.torque = angular * inverseH;
  return r;
}

}  // namespace rbsim
