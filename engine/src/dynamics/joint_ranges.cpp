#include "rbsim/dynamics/joint_ranges.h"

#include <cmath>

#include "rbsim/math/format_number.h"
#include "rbsim/math/physical_ranges.h"
#include "rbsim/math/types.h"

namespace rbsim {

namespace {
bool slider(JointDef::Type type) { return type == JointDef::Type::Prismatic; }
}  // namespace

const char* jointTypeName(JointDef::Type type) {
  switch (type) {
    case JointDef::Type::Ball: return "ball";
    case JointDef::Type::Hinge: return "hinge";
    case JointDef::Type::Prismatic: return "prismatic";
    case JointDef::Type::Weld: return "weld";
  }
  return "";
}

const char* maxMotorKey(JointDef::Type type) { return slider(type) ? "max_force" : "max_torque"; }

const char* limitsKey(JointDef::Type type) { return type == JointDef::Type::Ball ? "twist" : "limits"; }

std::string motorSpeedProblem(double speed, JointDef::Type type) {
  if (std::abs(speed) <= kMaxMotorSpeed) return {};
  return "expected a speed of at most " + formatNumber(kMaxMotorSpeed) + (slider(type) ? " m/s" : " rad/s") +
         " either way, got " + formatNumber(speed);
}

std::string maxMotorProblem(double max, JointDef::Type type) {
  const double bound = slider(type) ? kMaxMotorForce : kMaxMotorTorque;
  if (max >= 0.0 && max <= bound) return {};
  return std::string(slider(type) ? "expected a force from 0 to " : "expected a torque from 0 to ") + formatNumber(bound) +
         (slider(type) ? " N, got " : " N m, got ") + formatNumber(max);
}

std::string limitsExpectation(JointDef::Type type) {
  if (slider(type)) {
    return "expected [lower, upper] translations in m with lower <= upper, each within " + formatNumber(kMaxCoordinate) + " m";
  }
  return type == JointDef::Type::Ball ? "expected [lower, upper] twist angles in radians with -pi <= lower <= upper <= pi"
                                      : "expected [lower, upper] angles in radians with -pi <= lower <= upper <= pi";
}

std::string limitsProblem(double lower, double upper, JointDef::Type type) {
  const double bound = slider(type) ? kMaxCoordinate : kPi;
  return lower >= -bound && lower <= upper && upper <= bound ? std::string() : limitsExpectation(type);
}

}  // namespace rbsim
