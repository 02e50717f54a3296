#include "scene/ragdoll_parser.h"

#include <set>
#include <stdexcept>
#include <string>

#include "rbsim/world/made_names.h"
#include "rbsim/world/world.h"
#include "scene/input_ranges.h"
#include "scene/joint_parser.h"  // the joint springs' bounds, kMaxJointHertz and kMaxJointDampingRatio

namespace rbsim::scene_detail {

namespace {

// A figure from a doll to a giant: 0.05 to 20 times a 1.8 m person.

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
  // Every bone's mass and principal moments, and their inverses, within 1e+-150, as a listed
  // body's (body_parser.cpp, checkMassScale): a figure of 1e-300 kg failed as a divergence that
  // named no file or field (issue 56, item 5). The figure is built to read them.
  World probe{Settings{}};
  try {
    static_cast<void>(addRagdoll(probe, def));
  } catch (const std::invalid_argument& e) {
    r.fail("mass", std::string("a bone cannot be made: ") + e.what());
  }
  const auto inScale = [](double x) { return x <= kMaxMassScale && 1.0 / x <= kMaxMassScale; };
  for (const RigidBody& bone : probe.bodies()) {
    const double least = bone.principalMoments().minCoeff(), most = bone.principalMoments().maxCoeff();
    if (inScale(bone.mass()) && inScale(least) && inScale(most)) continue;
    r.fail("mass", "a figure of " + formatNumber(def.mass) + " kg at scale " + formatNumber(def.scale) + " gives its bone " +
                       bone.name().substr(def.name.size() + 1) + " a mass of " + formatNumber(bone.mass()) +
                       " kg and principal moments from " + formatNumber(least) + " to " + formatNumber(most) +
                       " kg m^2; expected each and its inverse within 1e+-150 (the solver multiplies one by another)");
  }
}

void parseRagdolls(const JsonObject& root, Scene& scene) {
  // Every name taken so far: the bodies' and the bones' of the ragdolls spawned at load. A ragdoll
  // takes exactly its eleven bones' names (issue 56, item 4: a body "left_x" no longer blocks a
  // ragdoll "left").
  std::set<std::string> taken, ragdollNames;
  for (const BodyDef& b : scene.bodies) taken.insert(b.name);
  for (const RagdollDef& spawned : scene.ragdolls) {
    ragdollNames.insert(spawned.name);
    for (const std::string& bone : ragdollBodyNames(spawned.name)) taken.insert(bone);
  }
  const std::vector<JsonObject> blocks = root.objectArray(
      "ragdolls", kRagdollKeys);
  std::set<std::string> given;
  for (const JsonObject& r : blocks) {
    if (r.has("name")) given.insert(r.string("name", ""));
  }
  // An unnamed ragdoll is ragdoll<n>, n its place among the blocks, or the first after that no
  // ragdoll has and whose bones' names are free.
  const auto free = [&](const std::string& name) {
    if (given.count(name) != 0 || ragdollNames.count(name) != 0) return false;
    for (const std::string& bone : ragdollBodyNames(name)) {
      if (taken.count(bone) != 0) return false;
    }
    return true;
  };
  std::size_t n = 0;
  for (const JsonObject& r : blocks) {
    RagdollDef def;
    if (r.has("name")) {
      def.name = r.string("name", "");
    } else {
      while (!free("ragdoll" + std::to_string(n))) ++n;
      def.name = "ragdoll" + std::to_string(n);
    }
    ++n;
    def.position = r.boundedVec3("position", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
    def.velocity = r.boundedVec3("velocity", Vec3::Zero(), kMaxSpeed, "m/s", "the speed of light");
    parseRagdollFigure(r, def);
    if (!ragdollNames.insert(def.name).second) {
      r.fail("name", "another ragdoll is named \"" + def.name + "\"; expected a name of its own");
    }
    for (const std::string& bone : ragdollBodyNames(def.name)) {
      if (!taken.insert(bone).second) {
        r.fail("name", "its bones are named " + def.name + "_pelvis, " + def.name + "_torso, ..., and a body is already named \"" +
                           bone + "\"; expected a name of its own");
      }
      for (const SpawnerDef& spawner : scene.spawners) {
        if (spawnerMakesName(spawner, bone)) r.fail("name", madeNameProblem(spawner, bone));
      }
    }
    scene.ragdolls.push_back(def);
  }
  if (!scene.ragdolls.empty() && scene.settings.solver != Settings::ContactSolverMethod::SoftStep) {
    root.fail("ragdolls", "a ragdoll's joints need the soft-step solver; expected world.solver \"soft-step\"");
  }
}

}  // namespace rbsim::scene_detail
