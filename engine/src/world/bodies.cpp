// World's bodies as a dense array with ids of a generation (body/body_id.h, as Box2D v3's
// b2BodyId): adding and destroying bodies, and keeping every per-body array in step with
// bodies_ (the materials, shapes, fracture patterns, the collision pipeline's data, and the
// scripts, springs and emitters that name a body by its index).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "rbsim/world/world.h"
#include "dynamics/contact_solver.h"
#include "world/collision_pipeline.h"
#include "world/swap_remove.h"

#include "rbsim/fracture/fracture.h"

namespace rbsim {

namespace {

constexpr std::uint32_t kNoSlot = UINT32_MAX;
// The contact solvers key a pair's manifolds by 24-bit body indices (dynamics/contact_key.h).
constexpr std::size_t kMaxBodies = (std::size_t{1} << 24) - 1;

// Removes the entries naming the body `removed`; the others name theirs by id, which stays.
template <typename T>
void removeNaming(std::vector<T>& items, BodyId removed) {
  items.erase(std::remove_if(items.begin(), items.end(), [&](const T& item) { return item.body == removed; }),
              items.end());
}

}  // namespace

BodyId World::addBody(const BodyDef& def) {
  if (bodies_.size() >= kMaxBodies) {
    throw std::invalid_argument("body '" + def.name + "': a World holds at most " + std::to_string(kMaxBodies) + " bodies");
  }
  const std::string problem = checkMaterial(def.material);
  if (!problem.empty()) throw std::invalid_argument("body '" + def.name + "': " + problem);
  if (def.fracture) {
    const std::string misfit = checkFracturePattern(*def.fracture, def);
    if (!misfit.empty()) throw std::invalid_argument("body '" + def.name + "': fracture: " + misfit);
  }
  bodies_.emplace_back(def);
  bodyMaterials_.push_back(def.material);
  bodySolids_.push_back(bodySolidOf(def));
  fracturePatterns_.push_back(def.fracture);
  if (def.fracture) ++breakableBodies_;
  collision_->addBody(bodies_.back(), bodySolids_.back());
  std::uint32_t slot = freeSlot_;
  if (slot == kNoSlot) {
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.push_back({});
  } else {
    freeSlot_ = slots_[slot].index;
  }
  slots_[slot].index = static_cast<std::uint32_t>(bodies_.size() - 1);
  slotOfBody_.push_back(slot);
  return {slot, slots_[slot].generation};
}

bool World::isValid(BodyId id) const {
  return id.slot < slots_.size() && slots_[id.slot].generation == id.generation &&
         slots_[id.slot].index < slotOfBody_.size() && slotOfBody_[slots_[id.slot].index] == id.slot;
}

std::size_t World::indexOf(BodyId id) const {
  if (!isValid(id)) {
    throw std::invalid_argument("body id (slot " + std::to_string(id.slot) + ", generation " +
                                std::to_string(id.generation) + ") names no body: destroyed, or never made here");
  }
  return slots_[id.slot].index;
}

BodyId World::idAt(std::size_t index) const {
  if (index >= bodies_.size()) throw std::invalid_argument("idAt: no body at index " + std::to_string(index));
  const std::uint32_t slot = slotOfBody_[index];
  return {slot, slots_[slot].generation};
}

void World::destroyBody(BodyId id) {
  const std::size_t removed = indexOf(id);
  const std::size_t last = bodies_.size() - 1;
  // Whatever rested on it must notice it is gone (as Box2D's b2DestroyBody wakes its contacts).
  for (const Contact& c : collision_->contacts()) {
    if (c.kind != Contact::Kind::BodyBody) continue;
    if (c.a == removed) bodies_[c.b].wake();
    if (c.b == removed) bodies_[c.a].wake();
  }
  // What names the body goes with it.
  removeNaming(forces_, id);
  removeNaming(springs_, id);
  removeNaming(pendingEvents_, id);
  removeNaming(motions_, id);
  // A joint goes with either of its bodies; its other body wakes to fall free.
  for (const Joint& joint : joints_) {
    const bool names = joint.a == removed || joint.b == removed;
    if (names && joint.a != removed) bodies_[joint.a].wake();
    if (names && joint.b != removed && joint.b != kWorldIndex) bodies_[joint.b].wake();
  }
  joints_.erase(std::remove_if(joints_.begin(), joints_.end(),
                               [&](const Joint& j) { return j.a == removed || j.b == removed; }),
                joints_.end());
  for (Joint& joint : joints_) {
    if (joint.a == last) joint.a = removed;
    if (joint.b == last) joint.b = removed;
  }
  // Warm starts are keyed by body indices: the moved body's follow it (read before the move).
  solver_->bodyRemoved(removed, last, bodies_);
  for (const std::unique_ptr<StepListener>& listener : listeners_) listener->bodyRemoved(removed, last, removed);
  if (fracturePatterns_[removed]) --breakableBodies_;
  swapRemove(bodies_, removed);
  swapRemove(bodyMaterials_, removed);
  swapRemove(bodySolids_, removed);
  swapRemove(fracturePatterns_, removed);
  collision_->removeBody(removed);
  updateJointFilter();
  // The id: the slot's generation moves on (every copy of the id is now stale), and the slot joins
  // the free list; the body moved into `removed` keeps its slot, which now points there.
  const std::uint32_t slot = id.slot;
  ++slots_[slot].generation;
  slots_[slot].index = freeSlot_;
  freeSlot_ = slot;
  if (removed != last) {
    slotOfBody_[removed] = slotOfBody_[last];
    slots_[slotOfBody_[removed]].index = static_cast<std::uint32_t>(removed);
  }
  slotOfBody_.pop_back();
}

void World::restore(std::uint64_t stepCount, const std::vector<BodyState>& states, const std::vector<char>& awake) {
  if (states.size() != bodies_.size() || awake.size() != bodies_.size()) {
    throw std::invalid_argument("World::restore: " + std::to_string(states.size()) + " states and " +
                                std::to_string(awake.size()) + " awake flags for " + std::to_string(bodies_.size()) +
                                " bodies");
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    RigidBody& body = bodies_[i];
    body.setState(states[i]);
    // A sleeping body's momenta are zero (RigidBody::sleep); sleep() keeps what was recorded.
    if (awake[i] != 0) {
      body.wake();
    } else if (!body.isStatic()) {
      body.sleep();
    }
  }
  stepCount_ = stepCount;
  timeOrigin_ = 0.0;  // a recording's steps all have its one time step
  stepsAtOrigin_ = 0;
}

}  // namespace rbsim
