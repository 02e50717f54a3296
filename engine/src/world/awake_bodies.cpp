// The awake bodies and the islands that sleep and wake (issue 58, "no scan of every body"; Box2D
// v3's solver sets, src/solver_set.c b2WakeSolverSet and b2TrySleepIsland, src/island.c): a step
// visits the awake bodies and their contacts alone. A sleeping island's contacts are kept apart by
// the collision pipeline (world/sleeping_contacts.h), neither collided nor solved, and come back
// when a body of the island wakes.
#include <algorithm>
#include <limits>

#include "dynamics/contact_solver.h"
#include "math/disjoint_sets.h"
#include "rbsim/world/world.h"
#include "world/collision_pipeline.h"
#include "world/contact_event_tracker.h"

namespace rbsim {

void World::rebuildAwake() {
  awakeList_.clear();
  table_->listed.assign(table_->bodies.size(), 0);
  for (std::size_t i = 0; i < table_->bodies.size(); ++i) {
    if (!table_->bodies[i].awake()) continue;
    table_->listed[i] = 1;
    awakeList_.push_back(static_cast<std::uint32_t>(i));
  }
  awakeSorted_ = true;
  awakeStale_ = false;
  awakeScanned_ = table_->bodies.size();
}

void World::refreshAwake() {
  if (awakeStale_) {
    rebuildAwake();
    return;
  }
  // Bodies added since: appended, each at the end of the table (a removal makes the list stale).
  if (table_->listed.size() < table_->bodies.size()) table_->listed.resize(table_->bodies.size(), 0);
  for (std::size_t i = awakeScanned_; i < table_->bodies.size(); ++i) {
    if (table_->bodies[i].awake()) listAwake(i);
  }
  awakeScanned_ = table_->bodies.size();
  // Those listed but not awake (handed out by body(id) and left asleep, or put to sleep) leave.
  std::size_t kept = 0;
  for (const std::uint32_t i : awakeList_) {
    if (table_->bodies[i].awake()) {
      awakeList_[kept++] = i;
    } else {
      table_->listed[i] = 0;
    }
  }
  awakeList_.resize(kept);
  if (!awakeSorted_) std::sort(awakeList_.begin(), awakeList_.end());
  awakeSorted_ = true;
}

void World::wakeBody(std::size_t index) {
  listAwake(index);  // first: a step's undo keeps the body as it was
  table_->bodies[index].wake();
}

void World::wakeIslandsOf(const std::vector<std::size_t>& seeds, bool solveNow) {
  std::vector<std::size_t> woken;
  std::vector<Contact> contacts;
  collision_->takeIslands(seeds, woken, contacts);
  for (const std::size_t i : woken) {
    if (!table_->bodies[i].awake() && !table_->bodies[i].isStatic()) wakeBody(i);
  }
  if (!contacts.empty()) {
    solver_->contactsWoke(contacts, bodyKeys());
    contactEvents_->contactsWoke(contacts, *collision_);
    if (solveNow) collision_->appendContacts(contacts);
  }
  refreshAwake();
}

void World::wakeListedIslands() {
  // A body woken between steps (body(id), a joint, a removal) or by this step's pose events and
  // forces wakes its island, which the collision stages then treat as awake (b2WakeSolverSet).
  std::vector<std::size_t> seeds;
  for (const std::uint32_t i : awakeList_) {
    if (collision_->keepsContactsOf(i)) seeds.push_back(i);
  }
  if (!seeds.empty()) wakeIslandsOf(seeds, /*solveNow=*/false);
}

void World::wakeTouchedIslands() {
  // A sleeping island touched by an awake body wakes whole, in the step of the touch (Box2D's
  // b2WakeSolverSet). Its kept contacts join this step's, so it wakes standing on them. Woken one
  // layer a step, each newly woken body fell a step with nothing under it, and woke the next.
  std::vector<std::size_t> seeds;
  for (const Contact& c : collision_->contacts()) {
    if (c.kind != Contact::Kind::BodyBody || table_->bodies[c.a].isStatic() || table_->bodies[c.b].isStatic()) continue;
    if (table_->bodies[c.a].awake() == table_->bodies[c.b].awake()) continue;
    seeds.push_back(table_->bodies[c.a].awake() ? c.b : c.a);
  }
  if (!seeds.empty()) wakeIslandsOf(seeds, /*solveNow=*/true);
}

void World::updateSleep() {
  // Run with skipIdleStages = false, the stage must still not put anything to sleep.
  if (!settings_.allowSleep) return;
  const double dt = settings_.timeStep;
  refreshAwake();
  const std::size_t m = awakeList_.size();
  localIndex_.resize(table_->bodies.size());
  for (std::size_t k = 0; k < m; ++k) {
    RigidBody& body = table_->bodies[awakeList_[k]];
    localIndex_[awakeList_[k]] = static_cast<std::uint32_t>(k);
    // A kinematic body that moves at all is never at rest: sleeping would stop it.
    const bool still = !body.isKinematic() || (body.velocity().isZero(0.0) && body.angularVelocity().isZero(0.0));
    const bool slow = still && body.velocity().norm() < settings_.sleepLinearSpeed &&
                      body.angularVelocity().norm() < settings_.sleepAngularSpeed;
    body.setRestingTime(slow ? body.restingTime() + dt : 0.0);
  }
  // An island sleeps when its least rested body has rested long enough. Islands over the awake
  // bodies, by their places in awakeList_: a sleeping body's contacts are kept apart.
  const auto local = [&](std::size_t i) {
    const std::size_t k = i < localIndex_.size() ? localIndex_[i] : m;
    return k < m && awakeList_[k] == i ? k : m;
  };
  DisjointSets islands(m);
  for (const Contact& contact : collision_->contacts()) {
    if (contact.kind != Contact::Kind::BodyBody || table_->bodies[contact.a].isStatic() || table_->bodies[contact.b].isStatic()) continue;
    const std::size_t a = local(contact.a), b = local(contact.b);
    if (a < m && b < m) islands.link(a, b);
  }
  for (const Joint& joint : joints_) {  // jointed bodies sleep together (Box2D's b2LinkJoint)
    if (joint.def.bodyB == kWorldAnchor) continue;
    const std::size_t indexB = table_->ids.indexOf(joint.def.bodyB);
    if (table_->bodies[indexB].isStatic()) continue;
    const std::size_t a = local(table_->ids.indexOf(joint.def.bodyA)), b = local(indexB);
    if (a < m && b < m) islands.link(a, b);
  }
  std::vector<double>& rested = islandRestingTime_;
  rested.assign(m, std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < m; ++k) {
    double& least = rested[islands.find(k)];
    least = std::min(least, table_->bodies[awakeList_[k]].restingTime());
  }
  bool slept = false;
  for (std::size_t k = 0; k < m; ++k) {
    if (rested[islands.find(k)] >= settings_.timeToSleep) {
      table_->bodies[awakeList_[k]].sleep();
      slept = true;
    }
  }
  if (!slept) return;
  refreshAwake();
  // The integrate and continuous stages have read which bodies the solve advanced: the list of
  // the step's bodies goes now, not at the next removal or step.
  solver_->clearAdvanced();
  sleepContacts();
}

void World::sleepContacts() {
  static_assert(CollisionPipeline::kNoContact == ContactSolver::kDroppedContact, "one mark for a contact that slept");
  std::vector<std::uint32_t> newIndex;
  collision_->sleepContacts(newIndex);
  if (collision_->sleptNow().empty()) return;
  solver_->contactsSlept(collision_->sleptNow(), bodyKeys());
  solver_->contactsReindexed(newIndex);
  contactEvents_->contactsSlept(collision_->sleptNow(), *collision_, newIndex);
}

}  // namespace rbsim
