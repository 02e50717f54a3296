// The World's joints (dynamics/joint.h): adding one, waking and filtering the bodies it links.
// The soft step solves them (dynamics/soft_step_joints.cpp); islands.h puts both bodies of a
// joint in one island (World::updateSleep).
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/world/world.h"
#include "dynamics/contact_solver.h"
#include "rbsim/math/types.h"
#include "world/collision_pipeline.h"

namespace rbsim {

JointId World::addJoint(const JointDef& def) {
  const std::string who = "joint" + (def.name.empty() ? std::string() : " '" + def.name + "'");
  if (!solver_->solvesJoints()) {
    throw std::invalid_argument(who + ": joints need the soft-step solver (world.solver \"soft-step\"); " +
                                std::string(settings_.solver == Settings::ContactSolverMethod::Pgs ? "PGS" : "LCP") +
                                " does not solve them");
  }
  if (!isValid(def.bodyA)) throw std::invalid_argument(who + ": body_a names no body");
  const bool world = def.bodyB == kWorldAnchor;
  if (!world && !isValid(def.bodyB)) throw std::invalid_argument(who + ": body_b names no body");
  if (def.bodyA == def.bodyB) throw std::invalid_argument(who + ": body_a and body_b are the same body");
  const std::size_t ia = indexOf(def.bodyA), ib = world ? 0 : indexOf(def.bodyB);  // ib: B's, when a body
  if (!table_->bodies[ia].isDynamic()) {
    throw std::invalid_argument(who + ": body_a '" + table_->bodies[ia].name() + "' must be dynamic (neither static nor kinematic)");
  }
  if (!def.anchor.allFinite() || !def.axis.allFinite() || !(def.axis.norm() > 0.0)) {
    throw std::invalid_argument(who + ": expected a finite anchor and a finite, non-zero axis");
  }
  using Type = JointDef::Type;
  const bool prismatic = def.type == Type::Prismatic;
  const auto nonNegative = [](double x) { return std::isfinite(x) && x >= 0.0; };
  if (def.motor && (def.type == Type::Ball || def.type == Type::Weld)) {
    throw std::invalid_argument(who + ": only a hinge or a prismatic joint takes a motor");
  }
  if (def.motor && (!std::isfinite(def.motorSpeed) || !nonNegative(prismatic ? def.maxMotorForce : def.maxMotorTorque))) {
    throw std::invalid_argument(who + (prismatic ? ": expected a finite motor speed and a finite max force >= 0"
                                                 : ": expected a finite motor speed and a finite max torque >= 0"));
  }
  if (def.limits && def.type == Type::Weld) throw std::invalid_argument(who + ": a weld joint takes no limits");
  if (def.limits && prismatic &&
      !(std::isfinite(def.lowerTranslation) && std::isfinite(def.upperTranslation) && def.lowerTranslation <= def.upperTranslation)) {
    throw std::invalid_argument(who + ": expected finite translation limits lower <= upper");
  }
  if (def.limits && !prismatic && !(def.lowerAngle >= -kPi && def.lowerAngle <= def.upperAngle && def.upperAngle <= kPi)) {
    throw std::invalid_argument(who + ": expected limits -pi <= lower <= upper <= pi");
  }
  if (def.coneLimit && def.type != Type::Ball) throw std::invalid_argument(who + ": only a ball joint takes a cone limit");
  if (def.coneLimit && !(def.coneAngle >= 0.0 && def.coneAngle <= kPi)) {
    throw std::invalid_argument(who + ": expected a cone half-angle from 0 to pi");
  }
  if ((def.spring || def.friction != 0.0) && def.type == Type::Weld) {
    throw std::invalid_argument(who + ": a weld joint takes no spring or friction; its softness is linear_hertz and angular_hertz");
  }
  if (def.spring && !(nonNegative(def.springHertz) && def.springHertz > 0.0 && nonNegative(def.springDampingRatio))) {
    throw std::invalid_argument(who + ": expected a spring of finite hertz > 0 and a finite damping ratio >= 0");
  }
  if (!nonNegative(def.friction)) throw std::invalid_argument(who + ": expected a finite friction >= 0");
  if (!nonNegative(def.linearHertz) || !nonNegative(def.linearDampingRatio) || !nonNegative(def.angularHertz) ||
      !nonNegative(def.angularDampingRatio)) {
    throw std::invalid_argument(who + ": expected finite weld hertz and damping ratios >= 0");
  }
  Joint joint;
  joint.def = def;
  joint.def.axis = def.axis.normalized();
  const RigidBody& a = table_->bodies[ia];
  const Quat baseOrientation = world ? Quat::Identity() : table_->bodies[ib].orientation();
  const Vec3 basePosition = world ? Vec3::Zero() : table_->bodies[ib].position();
  joint.localAnchorBase = baseOrientation.conjugate() * (def.anchor - basePosition);
  joint.localAxisBase = baseOrientation.conjugate() * joint.def.axis;
  joint.localAnchorMoving = a.orientation().conjugate() * (def.anchor - a.position());
  joint.localAxisMoving = a.orientation().conjugate() * joint.def.axis;
  joint.referenceRotation = baseOrientation.conjugate() * a.orientation();
  joints_.push_back(joint);
  wakeBody(ia);
  if (!world) wakeBody(ib);
  if (!world && !def.collideConnected) collision_->ignorePair(ia, ib);
  return jointIds_.add();
}

void World::wakeJointed() {
  // A body a joint wakes wakes its island, whose kept contacts are solved this step; that island
  // may hold the sleeping side of another joint, hence the rounds.
  for (bool woke = true; woke;) {
    woke = false;
    std::vector<std::size_t> seeds;
    for (const Joint& joint : joints_) {
      if (joint.def.bodyB == kWorldAnchor) continue;
      const std::size_t a = table_->ids.indexOf(joint.def.bodyA), b = table_->ids.indexOf(joint.def.bodyB);
      if (table_->bodies[b].isStatic() || table_->bodies[a].awake() == table_->bodies[b].awake()) continue;
      seeds.push_back(table_->bodies[a].awake() ? b : a);
      wakeBody(a);
      wakeBody(b);
      woke = true;
    }
    if (woke) wakeIslandsOf(seeds, /*solveNow=*/true);
  }
}

void World::updateJointFilter() {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const Joint& joint : joints_) {
    if (joint.def.bodyB != kWorldAnchor && !joint.def.collideConnected) {
      pairs.emplace_back(table_->ids.indexOf(joint.def.bodyA), table_->ids.indexOf(joint.def.bodyB));
    }
  }
  collision_->setIgnoredPairs(pairs);
}

}  // namespace rbsim
