#include "scene/ragdoll_parser.h"

#include <string>

#include "scene/input_ranges.h"
#include "scene/joint_parser.h"  // the joint springs' bounds, kMaxJointHertz and kMaxJointDampingRatio

namespace rbsim::scene_detail {

namespace {

// A figure from a doll to a giant: 0.05 to 20 times a 1.8 m person.
constexpr double kMinRagdollScale = 0.05;  // [1]
constexpr double kMaxRagdollScale = 20.0;  // [1]

}  // namespace

void parseRagdollFigure(const JsonObject& r, RagdollDef& def) {
  def.orientation = r.optionalOrientation("orientation").value_or(Quat::Identity());
  def.scale = r.positiveNumber("scale", def.scale);
  if (def.scale < kMinRagdollScale || def.scale > kMaxRagdollScale) {
    r.fail("scale", "expected " + formatNumber(kMinRagdollScale) + " to " + formatNumber(kMaxRagdollScale) + " (1: 1.8 m tall)");
  }
  def.mass = r.positiveNumber("mass", def.mass);
  if (def.mass > kMaxMassScale) r.fail("mass", "expected at most " + formatNumber(kMaxMassScale) + " kg");
  def.jointFriction = r.number("joint_friction", def.jointFriction);
  if (!(def.jointFriction >= 0.0) || def.jointFriction > kMaxMassScale) r.fail("joint_friction", "expected a torque >= 0 N m");
  def.jointHertz = r.number("joint_hertz", def.jointHertz);
  if (!(def.jointHertz >= 0.0) || def.jointHertz > kMaxJointHertz) {
    r.fail("joint_hertz", "expected a frequency from 0 (no spring) to " + formatNumber(kMaxJointHertz) + " Hz");
  }
  def.jointDampingRatio = r.number("joint_damping_ratio", def.jointDampingRatio);
  if (!(def.jointDampingRatio >= 0.0) || def.jointDampingRatio > kMaxJointDampingRatio) {
    r.fail("joint_damping_ratio", "expected a ratio from 0 to " + formatNumber(kMaxJointDampingRatio));
  }
}

void parseRagdolls(const JsonObject& root, Scene& scene) {
  int n = 0;
  for (const JsonObject& r : root.objectArray("ragdolls", {"name", "position", "orientation", "velocity", "scale", "mass",
                                                           "joint_friction", "joint_hertz", "joint_damping_ratio"})) {
    RagdollDef def;
    def.name = r.string("name", "ragdoll" + std::to_string(n++));
    def.position = r.boundedVec3("position", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
    def.velocity = r.boundedVec3("velocity", Vec3::Zero(), kMaxSpeed, "m/s", "the speed of light");
    parseRagdollFigure(r, def);
    for (const BodyDef& b : scene.bodies) {
      if (b.name.rfind(def.name + "_", 0) == 0) r.fail("name", "body \"" + b.name + "\" already starts with \"" + def.name + "_\"; expected a name of its own");
    }
    for (const RagdollDef& other : scene.ragdolls) {
      if (other.name == def.name) r.fail("name", "another ragdoll is named \"" + def.name + "\"; expected a name of its own");
    }
    scene.ragdolls.push_back(def);
  }
  if (!scene.ragdolls.empty() && scene.settings.solver != Settings::ContactSolverMethod::SoftStep) {
    root.fail("ragdolls", "a ragdoll's joints need the soft-step solver; expected world.solver \"soft-step\"");
  }
}

}  // namespace rbsim::scene_detail
