// Changes of a running World's joints (world/joint_changes.h: setJointMotor, setJointLimits, removeJoint;
// PyBullet's setJointMotorControl2 and removeConstraint, Box2D v3's b2RevoluteJoint_SetMotorSpeed,
// b2RevoluteJoint_SetLimits and b2DestroyJoint). Each checks before it changes anything, with the
// scene loader's checks (dynamics/joint_ranges.h), and wakes the joint's bodies.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "rbsim/dynamics/joint_ranges.h"
#include "rbsim/world/joint_changes.h"

#include "world/world_access.h"

namespace rbsim {

namespace {

// The joint's index, or std::invalid_argument naming the call.
std::size_t checkedIndex(const World& world, JointId joint, const char* call) {
  if (!isValid(world, joint)) {
    throw std::invalid_argument(std::string(call) + ": joint id (slot " + std::to_string(joint.slot) + ", generation " +
                                std::to_string(joint.generation) + ") is stale: the joint was removed, or never made here");
  }
  return WorldAccess::jointIds(world).indexOf(joint);
}

// "setJointMotor: joint 2 ('elbow')", the joint checked to exist; its index in `index`.
std::string who(const char* call, const World& world, JointId joint, std::size_t& index) {
  index = checkedIndex(world, joint, call);
  const std::string named = std::string(call) + ": joint " + std::to_string(index);
  const std::string& name = world.joints()[index].def.name;
  return name.empty() ? named : named + " ('" + name + "')";
}

void refuse(const std::string& who, const std::string& field, const std::string& problem) {
  if (!problem.empty()) throw std::invalid_argument(who + ": " + field + ": " + problem);
}

void wakeBodies(World& world, const Joint& j) {
  WorldAccess::wakeBody(world, world.indexOf(j.def.bodyA));  // listed awake too (world/awake_bodies.cpp)
  if (j.def.bodyB != kWorldAnchor) WorldAccess::wakeBody(world, world.indexOf(j.def.bodyB));
}

}  // namespace

bool isValid(const World& world, JointId joint) { return WorldAccess::jointIds(world).isValid(joint); }

std::size_t indexOf(const World& world, JointId joint) { return checkedIndex(world, joint, "indexOf"); }

JointId jointIdAt(const World& world, std::size_t index) {
  if (index >= world.joints().size()) throw std::invalid_argument("jointIdAt: no joint at index " + std::to_string(index));
  return WorldAccess::jointIds(world).idAt(index);
}

void setJointMotor(World& world, JointId joint, bool on, double speed, double maxTorque) {
  std::vector<Joint>& joints = WorldAccess::joints(world);
  std::size_t index = 0;
  const std::string name = who("setJointMotor", world, joint, index);
  Joint& j = joints[index];
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
    const double cap = world.settings().timeStep / world.settings().substeps * maxTorque;
    j.motorImpulse = std::clamp(j.motorImpulse, -cap, cap);
  }
  j.def.motor = on;  // off: the solver forgets its impulse (soft_step_joints.cpp)
  wakeBodies(world, j);
}

void setJointLimits(World& world, JointId joint, bool on, double lower, double upper) {
  std::vector<Joint>& joints = WorldAccess::joints(world);
  std::size_t index = 0;
  const std::string name = who("setJointLimits", world, joint, index);
  Joint& j = joints[index];
  const JointDef::Type type = j.def.type;
  if (type == JointDef::Type::Weld) refuse(name, "limits", "a weld joint takes no limits");
  if (on) {
    refuse(name, limitsKey(type), limitsProblem(lower, upper, type));
    (type == JointDef::Type::Prismatic ? j.def.lowerTranslation : j.def.lowerAngle) = lower;
    (type == JointDef::Type::Prismatic ? j.def.upperTranslation : j.def.upperAngle) = upper;
  }
  j.def.limits = on;
  j.lowerImpulse = j.upperImpulse = 0.0;
  wakeBodies(world, j);
}

void removeJoint(World& world, JointId joint) {
  std::size_t index = 0;
  who("removeJoint", world, joint, index);
  const Joint removed = world.joints()[index];
  WorldAccess::jointIds(world).eraseAt(WorldAccess::joints(world), index);
  WorldAccess::updateJointFilter(world);  // the pair may collide again, unless another joint holds it apart
  wakeBodies(world, removed);
}

}  // namespace rbsim
