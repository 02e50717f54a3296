#pragma once
// Changes of a running World's joints (PyBullet's setJointMotorControl2 and removeConstraint;
// Box2D v3's b2RevoluteJoint_SetMotorSpeed, b2RevoluteJoint_SetLimits and b2DestroyJoint;
// engine/src/world/joint_changes.cpp), from the next step on: free functions over World
// (docs/architecture.md, "The World's surface"). Each is checked with the scene loader's ranges
// and words (dynamics/joint_ranges.h) and throws std::invalid_argument naming the call, the joint
// (its index in World::joints() and name), the field and what was expected, the World unchanged;
// a stale id (the joint removed, by hand or with one of its bodies, or never made here: World::
// addJoint's JointId, world/item_ids.h) is refused the same way. Each wakes the joint's bodies.
#include "rbsim/world/item_ids.h"

namespace rbsim {

class World;

// A joint's id and its index in World::joints(), as for bodies: false / std::invalid_argument
// naming the call for a stale id (the joint removed, or never made here); jointIdAt throws when
// out of range.
bool isValid(const World& world, JointId joint);
std::size_t indexOf(const World& world, JointId joint);
JointId jointIdAt(const World& world, std::size_t index);

// A hinge's or slider's motor, on with a target speed [rad/s; m/s] and a largest torque [N m]
// (a slider's force [N]), or off (speed and max are then not read). A lower cap clamps the
// impulse kept for the warm start to it.
void setJointMotor(World& world, JointId joint, bool on, double speed, double maxTorque);
// A hinge's angle limits, a ball's twist limits, a slider's translation limits, or none (off);
// the limits' warm starts are forgotten, as Box2D v3's b2RevoluteJoint_SetLimits does.
void setJointLimits(World& world, JointId joint, bool on, double lower, double upper);
// Removes the joint, whose id goes stale; later joints move down one index in World::joints(),
// their ids unchanged. Its bodies wake and collide with each other again unless their filters or
// another joint say otherwise.
void removeJoint(World& world, JointId joint);

}  // namespace rbsim
