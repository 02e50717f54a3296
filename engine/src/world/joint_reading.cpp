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
  const RigidBody& a = world.bodies()[joint.a];
  const bool onWorld = joint.b == kWorldIndex;
  const Quat baseOrientation = onWorld ? Quat::Identity() : world.bodies()[joint.b].orientation();
  const Vec3 baseOmega = onWorld ? Vec3::Zero() : world.bodies()[joint.b].angularVelocity();

  JointReading r;
  r.axis = (baseOrientation * joint.localAxisBase).normalized();
  r.anchorA = a.position() + a.rotation() * joint.localAnchorMoving;
  r.anchorB = onWorld ? joint.localAnchorBase
                      : Vec3(world.bodies()[joint.b].position() + world.bodies()[joint.b].rotation() * joint.localAnchorBase);
  if (joint.def.type == JointDef::Type::Hinge) {
    r.angle = hingeAngle(joint, baseOrientation, a.orientation());
    r.speed = r.axis.dot(a.angularVelocity() - baseOmega);
  } else {
    r.angle = r.speed = std::numeric_limits<double>::quiet_NaN();
  }
  // soft_step_joints.cpp applies +impulse to A (its "moving" side) and keeps each substep's.
  const Settings& s = world.settings();
  const double inverseH = static_cast<double>(s.substeps) / s.timeStep;
  r.force = joint.linearImpulse * inverseH;
  r.torque = (joint.angularImpulse + (joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse) * r.axis) * inverseH;
  return r;
}

}  // namespace rbsim
