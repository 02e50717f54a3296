// The contact stages of World::step: the two orders of the pipeline (ContactSolver::Order: soft
// step collides first and advances the bodies it finds in contact; PGS integrates first and
// answers the contacts of the new poses) and the SolveContacts stage itself.
#include <algorithm>
#include <cmath>

#include "dynamics/contact_solver.h"
#include "world/collision_pipeline.h"
#include "world/contact_event_tracker.h"
#include "rbsim/world/world.h"

namespace rbsim {

void World::stepCollideFirst(bool withGravity, bool awake, bool collides) {
  // Collision detection first, at the poses the last step left (Box2D v3's b2Collide before
  // b2Solve): the solver advances the bodies it finds in contact, the integrator the rest.
  // Speculative contacts (collision_pipeline.h) make up for the contacts of the step's motion.
  runStage(Stage::BroadPhase, collides && collision_->needsBroadPhase(awakeList_, planes_), [&] {
    if (settings_.detectCollisions) collision_->broadPhase(awakeList_);
  });
  runStage(Stage::NarrowPhase, collides && awake, [&] {
    if (!settings_.detectCollisions) return;
    collision_->narrowPhase(awakeList_, planes_, time());
    if (!collision_->sleptNow().empty()) solver_->contactsSlept(collision_->sleptNow(), bodyKeys());
    contactEvents_->afterNarrowPhase(*this, *collision_);
  });
  const bool sweeping = settings_.continuousCollision && collides && awake;
  if (sweeping) collision_->rememberStart(awakeList_);
  solver_->clearAdvanced();
  // Skipped narrow phases leave the last contacts in place for display: with nothing awake they
  // are contacts between sleeping bodies, which receive nothing.
  // Joints are solved with the contacts, so a scene with joints runs the stage every awake step.
  const bool contactsToSolve = !collision_->contacts().empty() && settings_.respondToContacts;
  runStage(Stage::SolveContacts, awake && (contactsToSolve || !joints_.empty()), [&] {
    if (contactsToSolve || !joints_.empty()) solveContacts(withGravity);
  });
  runStage(Stage::Integrate, awake, [&] { integrateBodies(withGravity); });
  runStage(Stage::ContinuousCollision, sweeping, [&] { collision_->continuous(awakeList_, planes_, &solver_->advancedFlags()); });
}

void World::stepIntegrateFirst(bool withGravity, bool awake, bool collides) {
  // Integrate first, then find and answer the contacts of the new poses (Catto, GDC 2005).
  const bool sweeping = settings_.continuousCollision && collides && awake;
  runStage(Stage::Integrate, awake, [&] {
    if (sweeping) collision_->rememberStart(awakeList_);
    integrateBodies(withGravity);
  });
  runStage(Stage::ContinuousCollision, sweeping, [&] { collision_->continuous(awakeList_, planes_); });
  runStage(Stage::BroadPhase, collides && collision_->needsBroadPhase(awakeList_, planes_), [&] {
    if (settings_.detectCollisions) collision_->broadPhase(awakeList_);
  });
  runStage(Stage::NarrowPhase, collides && awake, [&] {
    if (!settings_.detectCollisions) return;
    collision_->narrowPhase(awakeList_, planes_, time());
    if (!collision_->sleptNow().empty()) solver_->contactsSlept(collision_->sleptNow(), bodyKeys());
    contactEvents_->afterNarrowPhase(*this, *collision_);
  });
  runStage(Stage::SolveContacts, awake && !collision_->contacts().empty() && settings_.respondToContacts, [&] {
    if (settings_.respondToContacts) solveContacts(withGravity);
  });
}

void World::solveContacts(bool withGravity) {
  wakeTouchedIslands();
  if (solver_->solvesJoints()) wakeJointed();  // and the islands of the bodies it wakes
  static const std::vector<Contact> kNoContacts;
  const std::vector<Contact>& contacts = settings_.respondToContacts ? collision_->contacts() : kNoContacts;
  solver_->solve({table_->bodies, contacts, joints_, table_->ids, table_->materials, planeMaterials_, settings_, withGravity});
  contactEvents_->afterSolve(*this, *collision_, contacts, *solver_, settings_.hitEventSpeed);
  checkFinite(solver_->advancedBodies());
}

void World::checkFinite(const std::vector<std::size_t>& bodies) const {
  for (std::size_t i : bodies) {
    if (!isFinite(table_->bodies[i].state())) reportDivergence(table_->bodies[i], table_->bodies[i].state());
  }
}

}  // namespace rbsim
