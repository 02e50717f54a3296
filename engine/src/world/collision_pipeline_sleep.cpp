// The collision pipeline's side of sleeping islands (world/collision_pipeline.h, issue 58): the
// contacts kept apart while their island sleeps, and what the continuous stage looks at near a
// sweep.
#include <algorithm>

#include "world/collision_pipeline.h"

namespace rbsim {

bool CollisionPipeline::keptAsleep(const Contact& c) const {
  const std::vector<RigidBody>& bodies = table_->bodies;
  const bool plane = c.kind == Contact::Kind::PlaneBody;
  if (bodies[c.b].awake() || (!plane && bodies[c.a].awake())) return false;
  // A pair with a compound or a mesh ground keeps all its contacts, one per part; a pair with a
  // grid, whose several manifolds are found afresh, none (both as before issue 58).
  const bool several = bodies[c.b].isCompound() || (!plane && (bodies[c.a].isCompound() || table_->meshGround[c.a] || table_->meshGround[c.b]));
  if (c.part != 0 && !several) return false;
  return plane || several || (table_->hasGrid[c.a] == 0 && table_->hasGrid[c.b] == 0);
}

void CollisionPipeline::keepSleeping() {
  sleptNow_.clear();
  for (const Contact& c : contacts_) {
    if (!keptAsleep(c)) continue;
    sleeping_.add(c, table_->bodies);
    sleptNow_.push_back(c);
  }
}

void CollisionPipeline::sleepContacts(std::vector<std::uint32_t>& newIndex) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  sleptNow_.clear();
  newIndex.resize(contacts_.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const Contact& c = contacts_[i];
    if (keptAsleep(c)) {
      sleeping_.add(c, bodies);
      sleptNow_.push_back(c);
      newIndex[i] = kNoContact;
      continue;
    }
    newIndex[i] = static_cast<std::uint32_t>(kept);
    if (kept != i) contacts_[kept] = c;
    ++kept;
  }
  contacts_.resize(kept);
  reportedStale_ = true;
  std::vector<ProxyId> asleep;
  for (const ProxyId p : broad_->awakeAtUpdate()) {
    if (!bodies[bodyOfProxy_[p]].awake()) asleep.push_back(p);
  }
  broad_->rest(asleep);
}

void CollisionPipeline::takeIslands(const std::vector<std::size_t>& seeds, std::vector<std::size_t>& islandBodies,
                                    std::vector<Contact>& contacts) {
  const std::vector<RigidBody>& bodies = table_->bodies;
  const std::size_t first = islandBodies.size();
  sleeping_.takeIslands(seeds, bodies, islandBodies, contacts);
  // A body woken now has not moved in this step: its start is where it is (rememberStart may
  // have run before it woke).
  for (std::size_t k = first; k < islandBodies.size(); ++k) table_->start[islandBodies[k]] = bodies[islandBodies[k]].state();
  reportedStale_ = true;
}

const std::vector<Contact>& CollisionPipeline::reported() const {
  if (sleeping_.empty()) return contacts_;
  if (reportedStale_) {
    reported_ = contacts_;
    sleeping_.all(reported_);
    reportedStale_ = false;
  }
  return reported_;
}

void CollisionPipeline::nearSweep(const Aabb& box, const std::vector<std::uint32_t>& awake,
                                  std::vector<std::size_t>& out) const {
  out.assign(awake.begin(), awake.end());
  for (const ProxyId p : broad_->awakeAtUpdate()) out.push_back(bodyOfProxy_[p]);
  restingNear_.clear();
  broad_->resting(box, restingNear_);
  for (const ProxyId p : restingNear_) out.push_back(bodyOfProxy_[p]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace rbsim
