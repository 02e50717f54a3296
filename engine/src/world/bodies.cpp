// World's bodies as a dense table with ids of a generation (world/body_table.h; body/body_id.h,
// as Box2D v3's b2BodyId): adding and destroying bodies, and what names a body (contacts, warm
// starts, scripts, springs, joints, the step listeners' emitters) following a removal.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "rbsim/world/world.h"
#include "dynamics/contact_key.h"
#include "dynamics/contact_solver.h"
#include "world/collision_pipeline.h"
#include "world/contact_event_tracker.h"
#include "body/body_removal.h"

#include "rbsim/fracture/fracture.h"

namespace rbsim {

namespace {

// The contact solvers key a pair's manifolds by 24-bit body indices (dynamics/contact_key.h).
constexpr std::size_t kMaxBodies = (std::size_t{1} << 24) - 1;

}  // namespace

template <typename T>
void World::removeStale(std::vector<T>& items) const {
  items.erase(std::remove_if(items.begin(), items.end(), [&](const T& item) { return !isValid(item.body); }), items.end());
}

BodyId World::addBody(const BodyDef& def) {
  if (table_->bodies.size() >= kMaxBodies) {
    throw std::invalid_argument("body '" + def.name + "': a World holds at most " + std::to_string(kMaxBodies) + " bodies");
  }
  const std::string problem = checkMaterial(def.material);
  if (!problem.empty()) throw std::invalid_argument("body '" + def.name + "': " + problem);
  if (def.fracture) {
    const std::string misfit = checkFracturePattern(*def.fracture, def);
    if (!misfit.empty()) throw std::invalid_argument("body '" + def.name + "': fracture: " + misfit);
  }
  // A row in every column (world/body_table.h), then the collision pipeline's measures of it.
  const BodyId id = table_->add(def);
  ++geometryVersion_;
  if (def.fracture) ++breakableBodies_;
  collision_->addBody(table_->size() - 1);
  return id;
}

bool World::isValid(BodyId id) const { return table_->ids.isValid(id); }

std::size_t World::indexOf(BodyId id) const {
  if (!isValid(id)) {
    throw std::invalid_argument("body id (slot " + std::to_string(id.slot) + ", generation " +
                                std::to_string(id.generation) + ") names no body: destroyed, or never made here");
  }
  return table_->ids.indexOf(id);
}

BodyId World::idAt(std::size_t index) const {
  if (index >= table_->bodies.size()) throw std::invalid_argument("idAt: no body at index " + std::to_string(index));
  return table_->ids.idAt(index);
}

void World::destroyBody(BodyId id) { destroyBodies({id}); }

void World::destroyBodies(const std::vector<BodyId>& ids) {
  // Every id is checked before anything changes: a stale or repeated one leaves the World as it was.
  // A set of the listed slots, not a flag per slot: the check costs the batch, not the World.
  std::unordered_set<std::uint32_t> listed;
  listed.reserve(ids.size());
  for (const BodyId id : ids) {
    static_cast<void>(indexOf(id));  // throws on a stale id
    if (!listed.insert(id.slot).second) {
      throw std::invalid_argument("destroyBodies: body '" + body(id).name() + "' (slot " + std::to_string(id.slot) +
                                  ") is listed twice");
    }
  }
  if (ids.empty()) return;
  // Their touching pairs end, named while the ids are still valid.
  std::vector<std::uint32_t> gone;
  gone.reserve(ids.size());
  for (const BodyId id : ids) gone.push_back(static_cast<std::uint32_t>(table_->ids.indexOf(id)));
  std::sort(gone.begin(), gone.end());
  contactEvents_->bodiesRemoving(*this, *collision_, gone);
  ++geometryVersion_;
  // The ids (and their shapes' ids), as destroyBody one after another: each slot's generation
  // moves on (every copy of the id is now stale) and the slot joins the free list; the last body
  // moves into the removed one's row, keeping its slot, which now points there. The rows stay
  // where they were until the table's gather below: every part reads its own first.
  const BodyRemoval removal = table_->retire(ids);
  // Whatever rested on a removed body must notice it is gone (as Box2D's b2DestroyBody wakes its
  // contacts); the contacts follow their bodies. Woken through wakeBody, indices before the
  // removal: the awake list is renumbered with the rest below.
  std::vector<std::size_t> touched;
  std::vector<Contact> reached;
  collision_->removeBodies(removal, touched, reached);
  for (const std::size_t partner : touched) wakeBody(partner);
  // What names a removed body goes with it (every id these name was valid before the batch).
  removeStale(forces_);
  // A spring or joint goes with its body; their ids go stale, their slots freed in the order one
  // destroyBody after another frees them (IdTable::eraseRanked): by the rank in `ids` of the first
  // removed body they name. Ranks by slot, looked up by binary search.
  std::vector<std::pair<std::uint32_t, std::size_t>> rankOfSlot;
  for (std::size_t r = 0; r < ids.size(); ++r) rankOfSlot.emplace_back(ids[r].slot, r);
  std::sort(rankOfSlot.begin(), rankOfSlot.end());
  const auto rankOf = [&](BodyId id) {
    return std::lower_bound(rankOfSlot.begin(), rankOfSlot.end(), std::make_pair(id.slot, std::size_t{0}))->second;
  };
  springIds_.eraseRanked(springs_, [&](const Spring& spring) {
    return isValid(spring.body) ? IdTable<SpringId>::kKept : rankOf(spring.body);
  });
  removeStale(pendingEvents_);
  removeStale(motions_);
  // A joint goes with either of its bodies (named by id: the others need nothing); its other body
  // wakes to fall free, by its index after the removal, once the bodies are gathered below.
  std::vector<BodyId> partners;
  jointIds_.eraseRanked(joints_, [&](const Joint& joint) {
    const BodyId a = joint.def.bodyA, b = joint.def.bodyB;
    const bool goneA = !isValid(a), goneB = b != kWorldAnchor && !isValid(b);
    if (!goneA && !goneB) return IdTable<JointId>::kKept;
    if (!goneA) partners.push_back(a);
    if (!goneB && b != kWorldAnchor) partners.push_back(b);
    return std::min(goneA ? rankOf(a) : IdTable<JointId>::kKept, goneB ? rankOf(b) : IdTable<JointId>::kKept);
  });
  // Warm starts are keyed by the bodies' stable keys (dynamics/contact_key.h pairKey): the
  // removed bodies' go and nothing else is renamed. A sleeping contact that went is named by its
  // bodies' keys before the batch, a removed body's being its id's slot.
  std::vector<std::uint32_t> removedKeys;
  removedKeys.reserve(ids.size());
  for (const BodyId id : ids) removedKeys.push_back(id.slot);
  std::sort(removedKeys.begin(), removedKeys.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> removedKeyAt;  // (index before, slot), sorted
  for (std::size_t r = 0; r < ids.size(); ++r) removedKeyAt.emplace_back(removal.removed()[r], ids[r].slot);
  std::sort(removedKeyAt.begin(), removedKeyAt.end());
  const auto keyBefore = [&](std::size_t index) -> std::uint64_t {
    const std::uint32_t to = removal.newIndex(index);
    if (to != BodyRemoval::kGone) return bodyKeys()[to];
    return std::lower_bound(removedKeyAt.begin(), removedKeyAt.end(), std::make_pair(static_cast<std::uint32_t>(index), 0u))->second;
  };
  std::vector<std::uint64_t> goneAsleep;
  for (const Contact& c : reached) {
    const bool plane = c.kind == Contact::Kind::PlaneBody;
    if (removal.newIndex(c.b) != BodyRemoval::kGone && (plane || removal.newIndex(c.a) != BodyRemoval::kGone)) continue;
    goneAsleep.push_back(pairKey(c.kind, c.part, plane ? c.a : keyBefore(c.a), keyBefore(c.b)));
  }
  solver_->bodiesRemoved(removedKeys, goneAsleep);
  for (const BodyRemoval::Step& s : removal.steps()) {
    for (const std::unique_ptr<StepListener>& listener : listeners_) listener->bodyRemoved(s.removed, s.last, s.removed);
  }
  for (const std::uint32_t gone : removal.removed()) {
    if (table_->fracturePatterns[gone]) --breakableBodies_;
  }
  // Every column at once, the collision pipeline's included (world/body_table.h).
  table_->gather(removal);
  renumberAwake(removal);
  for (const BodyId partner : partners) wakeBody(indexOf(partner));
  updateJointFilter();
}

void World::renumberAwake(const BodyRemoval& removal) {
  // The awake list follows the removal (a scan of every body to rebuild it would cost the World,
  // not the removal): the removed leave it, the moved take their new indices.
  std::size_t kept = 0;
  for (const std::uint32_t i : awakeList_) {
    const std::uint32_t to = removal.newIndex(i);
    if (to == BodyRemoval::kGone) continue;
    if (to != i) awakeSorted_ = false;
    awakeList_[kept++] = to;
  }
  awakeList_.resize(kept);
  // A body refreshAwake has not looked at yet (added since) may have moved below the mark.
  for (const auto& [to, from] : removal.moves()) {
    if (from >= awakeScanned_ && table_->bodies[to].awake()) listAwake(to);
  }
  awakeScanned_ = std::min(awakeScanned_, removal.after());
}

void World::restore(std::uint64_t stepCount, const std::vector<BodyState>& states, const std::vector<char>& awake) {
  if (states.size() != table_->bodies.size() || awake.size() != table_->bodies.size()) {
    throw std::invalid_argument("World::restore: " + std::to_string(states.size()) + " states and " +
                                std::to_string(awake.size()) + " awake flags for " + std::to_string(table_->bodies.size()) +
                                " bodies");
  }
  for (std::size_t i = 0; i < table_->bodies.size(); ++i) {
    RigidBody& body = table_->bodies[i];
    body.setState(states[i]);
    // A sleeping body's momenta are zero (RigidBody::sleep); sleep() keeps what was recorded.
    if (awake[i] != 0) {
      body.wake();
    } else if (!body.isStatic()) {
      body.sleep();
    }
  }
  stepCount_ = stepCount;
  ++geometryVersion_;
  awakeStale_ = true;  // flags set here, not through wakeBody
  timeOrigin_ = 0.0;  // a recording's steps all have its one time step
  stepsAtOrigin_ = 0;
}

}  // namespace rbsim
