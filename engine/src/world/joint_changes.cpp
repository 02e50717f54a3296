// Changes of a running World's joints (World::setJointMotor, setJointLimits, removeJoint;
// PyBullet's setJointMotorControl2 and removeConstraint, Box2D v3's b2RevoluteJoint_SetMotorSpeed,
// b2RevoluteJoint_SetLimits and b2DestroyJoint). Each checks before it changes anything, with the
// scene loader's checks (dynamics/joint_ranges.h), and wakes the joint's bodies.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "rbsim/dynamics/joint_ranges.h"
#include "rbsim/world/world.h"

namespace rbsim {

namespace {

// "World::setJointMotor: joint 2 ('elbow')", the joint checked to exist.
std::string who(const char* call, const std::vector<Joint>& joints, std::size_t joint) {
  const std::string named = std::string(call) + ": joint " + std::to_string(joint);
  if (joint >= joints.size()) {
    throw std::invalid_argument(named + ": no such joint; expected an index below " + std::to_string(joints.size()));
  }
  const std::string& name = joints[joint].def.name;
  return name.empty() ? named : named + " ('" + name + "')";
}

void refuse(const std::string& who, const std::string& field, const std::string& problem) {
  if (!problem.empty()) throw std::invalid_argument(who + ": " + field + ": " + problem);
}

}  // namespace

void World::setJointMotor(std::size_t joint, bool on, double speed, double maxTorque) {
  const std::string name = who("World::setJointMotor", joints_, joint);
  Joint& j = joints_[joint];
  const JointDef::Type type = j.def.type;
  if (type != JointDef::Type::Hinge && type != JointDef::Type::Prismatic) {
    refuse(name, "motor", std::string("a ") + jointTypeName(type) + " joint takes no motor; expected a hinge or a prismatic joint");
  }
  if (on) {
    refuse(name, "motor.speed", motorSpeedProblem(speed, type));
    refuse(name, std::string("motor.") + maxMotorKey(type), maxMotorProblem(maxTorque, type));
    j.def.motorSpeed = speed;
    (type == JointDef::Type::Prismatic ? j.def.maxMotorForce : j.def.maxMotorTorque) = maxTorque;
    // The kept impulse is of a substep, |lambda| <= h max (soft_step_joints.cpp): a lower cap
    // holds it too, or the warm start would push with the old torque.
    const double cap = settings_.timeStep / settings_.substeps * maxTorque;
    j.motorImpulse = std::clamp(j.motorImpulse, -cap, cap);
  }
  j.def.motor = on;  // off: the solver forgets its impulse (soft_step_joints.cpp)
  wakeBody(j.a);
  if (j.b != kWorldIndex) wakeBody(j.b);
}

void World::setJointLimits(std::size_t joint, bool on, double lower, double upper) {
  const std::string name = who("World::setJointLimits", joints_, joint);
  Joint& j = joints_[joint];
  const JointDef::Type type = j.def.type;
  if (type == JointDef::Type::Weld) refuse(name, "limits", "a weld joint takes no limits");
  if (on) {
    refuse(name, limitsKey(type), limitsProblem(lower, upper, type));
    (type == JointDef::Type::Prismatic ? j.def.lowerTranslation : j.def.lowerAngle) = lower;
    (type == JointDef::Type::Prismatic ? j.def.upperTranslation : j.def.upperAngle) = upper;
  }
  j.def.limits = on;
  j.lowerImpulse = j.upperImpulse = 0.0;
  wakeBody(j.a);
  if (j.b != kWorldIndex) wakeBody(j.b);
}

void World::removeJoint(std::size_t joint) {
  who("World::removeJoint", joints_, joint);
  const Joint removed = joints_[joint];
  joints_.erase(joints_.begin() + static_cast<std::ptrdiff_t>(joint));
  updateJointFilter();  // the pair may collide again, unless another joint holds it apart
  wakeBody(removed.a);
  if (removed.b != kWorldIndex) wakeBody(removed.b);
}

}  // namespace rbsim
