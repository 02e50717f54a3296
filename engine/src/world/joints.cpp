// The World's joints (dynamics/joint.h): adding one, waking and filtering the bodies it links.
// The soft step solves them (dynamics/soft_step_joints.cpp); islands.h puts both bodies of a
// joint in one island (World::updateSleep).
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/world/world.h"
#include "dynamics/contact_solver.h"
#include "world/collision_pipeline.h"

namespace rbsim {

std::size_t World::addJoint(const JointDef& def) {
  const std::string who = "joint" + (def.name.empty() ? std::string() : " '" + def.name + "'");
  if (!solver_->solvesJoints()) {
    throw std::invalid_argument(who + ": joints need the soft-step solver (world.solver \"soft-step\"); PGS does not solve them");
  }
  if (!isValid(def.bodyA)) throw std::invalid_argument(who + ": body_a names no body");
  const bool world = def.bodyB == kWorldAnchor;
  if (!world && !isValid(def.bodyB)) throw std::invalid_argument(who + ": body_b names no body");
  if (def.bodyA == def.bodyB) throw std::invalid_argument(who + ": body_a and body_b are the same body");
  const std::size_t ia = indexOf(def.bodyA), ib = world ? kWorldIndex : indexOf(def.bodyB);
  if (!bodies_[ia].isDynamic()) {
    throw std::invalid_argument(who + ": body_a '" + bodies_[ia].name() + "' must be dynamic (neither static nor kinematic)");
  }
  if (!def.anchor.allFinite() || !def.axis.allFinite() || !(def.axis.norm() > 0.0)) {
    throw std::invalid_argument(who + ": expected a finite anchor and a finite, non-zero axis");
  }
  if (def.motor && (!std::isfinite(def.motorSpeed) || !std::isfinite(def.maxMotorTorque) || !(def.maxMotorTorque >= 0.0))) {
    throw std::invalid_argument(who + ": expected a finite motor speed and a finite max torque >= 0");
  }
  if (def.limits && !(def.lowerAngle >= -M_PI && def.lowerAngle <= def.upperAngle && def.upperAngle <= M_PI)) {
    throw std::invalid_argument(who + ": expected limits -pi <= lower <= upper <= pi");
  }
  Joint joint;
  joint.def = def;
  joint.def.axis = def.axis.normalized();
  joint.a = ia;
  joint.b = ib;
  const RigidBody& a = bodies_[ia];
  const Quat baseOrientation = world ? Quat::Identity() : bodies_[ib].orientation();
  const Vec3 basePosition = world ? Vec3::Zero() : bodies_[ib].position();
  joint.localAnchorBase = baseOrientation.conjugate() * (def.anchor - basePosition);
  joint.localAxisBase = baseOrientation.conjugate() * joint.def.axis;
  joint.localAnchorMoving = a.orientation().conjugate() * (def.anchor - a.position());
  joint.localAxisMoving = a.orientation().conjugate() * joint.def.axis;
  joint.referenceRotation = baseOrientation.conjugate() * a.orientation();
  joints_.push_back(joint);
  bodies_[ia].wake();
  if (!world) bodies_[ib].wake();
  if (!world && !def.collideConnected) collision_->ignorePair(ia, ib);
  return joints_.size() - 1;
}

void World::wakeJointed() {
  for (const Joint& joint : joints_) {
    if (joint.b == kWorldIndex) continue;
    RigidBody& a = bodies_[joint.a];
    RigidBody& b = bodies_[joint.b];
    if (b.isStatic()) continue;
    if (a.awake() != b.awake()) {
      a.wake();
      b.wake();
    }
  }
}

void World::updateJointFilter() {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const Joint& joint : joints_) {
    if (joint.b != kWorldIndex && !joint.def.collideConnected) pairs.emplace_back(joint.a, joint.b);
  }
  collision_->setIgnoredPairs(pairs);
}

}  // namespace rbsim
