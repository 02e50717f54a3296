#pragma once
// A change to a running body or joint given as keys of the scene format (Python's World.set_body
// and World.set_joint), read with the scene loader's checks and messages over the values the body
// or joint has now: InputError naming `file` (the call) and the key. What comes back is what the
// World's own change calls take (setBodyMass, setBodyMaterial, setBodyFilter,
// setJointMotor, setJointLimits), checked, so a change that parses is one the World accepts.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "rbsim/body/material.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/shapes/collision_filter.h"

namespace rbsim {

inline constexpr std::initializer_list<const char*> kBodyChangeKeys = {
    "mass", "inertia", "restitution", "friction_static", "friction_kinetic", "filter"};

// Each set when its keys were given.
struct BodyChange {
  // "mass" [kg] and "inertia" (a 3 x 3 tensor about the centre of mass in the body frame, or its
  // three diagonal entries [kg m^2]), together. A mass alone scales the inertia with it (the same
  // shape, of uniform density: I' = I m' / m); an inertia alone keeps the mass.
  std::optional<double> mass;
  std::optional<Mat3> inertia;
  bool inertiaGiven = false;  // the inertia is the caller's, not the body's scaled
  // "restitution", "friction_static", "friction_kinetic" over `material` (a lowered mu_s lowers
  // mu_k with it unless mu_k is given, as in a body block); refused for a compound body.
  std::optional<Material> material;
  // "filter": {"category", "mask", "group"}, keys left out keeping the body's; refused for a compound.
  std::optional<CollisionFilter> filter;
};
BodyChange parseBodyChange(const nlohmann::json& change, const std::string& file, const RigidBody& body,
                           const Material& material);

// The keys of a joint change: "motor" ({"speed", "max_torque"}, a slider's {"speed", "max_force"};
// keys left out keep a motor's values, a new motor states both; false: off) and "limits" (a
// ball's "twist"; [lower, upper], false: none).
inline constexpr std::initializer_list<const char*> kJointChangeKeys = {"motor", "limits", "twist"};
struct JointChange {
  JointDef def;  // the joint's definition with the change
  bool motor = false, limits = false;  // which was given
};
JointChange parseJointChange(const nlohmann::json& change, const std::string& file, const Joint& joint);

}  // namespace rbsim
