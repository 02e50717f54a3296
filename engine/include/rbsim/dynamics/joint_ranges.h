#pragma once
// The ranges of a joint's motor and limits, and the words that refuse a value outside them: one
// check for each, called by the scene loader (engine/src/scene/joint_parser.cpp) and by a change
// to a running World (setJointMotor, setJointLimits), so both say the same.
#include <string>

#include "rbsim/dynamics/joint.h"

namespace rbsim {

// A motor's physical ranges: |speed| up to 1e5 rad/s (a million rpm, past any real rotor) and a
// torque up to 1e12 N m (a hundred thousand times a ship's propeller shaft). Beyond them a motor
// is a typo, and 1e300 N m overflowed the impulse h tau into a motor that did nothing.
inline constexpr double kMaxMotorSpeed = 1e5;    // [rad/s], a slider's [m/s]
inline constexpr double kMaxMotorTorque = 1e12;  // [N m]
inline constexpr double kMaxMotorForce = 1e12;   // [N], a slider motor's

// "ball", "hinge", "prismatic" or "weld": the type as a scene names it.
const char* jointTypeName(JointDef::Type type);
// The key of the motor's largest torque (a hinge's "max_torque") or force (a slider's "max_force").
const char* maxMotorKey(JointDef::Type type);
// The key of the limits: a ball joint's are its "twist", the others' "limits".
const char* limitsKey(JointDef::Type type);

// Each empty when the value is usable, otherwise what was expected (and what was given).
std::string motorSpeedProblem(double speed, JointDef::Type type);
std::string maxMotorProblem(double max, JointDef::Type type);
// A hinge's angles and a ball's twist in [-pi, pi], a slider's translations within
// kMaxCoordinate, lower <= upper.
std::string limitsProblem(double lower, double upper, JointDef::Type type);
std::string limitsExpectation(JointDef::Type type);  // what limitsProblem says when it refuses

}  // namespace rbsim
