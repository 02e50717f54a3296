// A failed step is undone (issue 56, item 6; the brief: "a failed step leaves the World as it
// was"): a step that removes bodies from a copy of the whole World (World::step), one that only
// spawns by removing what it made (undoSpawns), and every step as follows. Before the stages
// that can fail, World::step keeps what they change that a retry reads, in arrays reused from
// step to step (no allocation once the World has stopped growing): the bodies the step may
// change, the awake ones and those it wakes (issue 58: O(awake), not O(bodies)).
#include <algorithm>
#include <utility>
#include <vector>

#include "rbsim/world/world.h"

namespace rbsim {

void World::saveUndo() {
  StepUndo& u = undo_;
  u.index.clear();
  u.states.clear();
  u.awake.clear();
  u.resting.clear();
  u.force.clear();
  u.torque.clear();
  u.bodyTorque.clear();
  u.rotations.clear();
  // What a step can change: the awake bodies (and those body(id) handed out since the last step),
  // and those it wakes, saved as listAwake lists them. A step listener may wake any body unseen.
  u.all = std::any_of(listeners_.begin(), listeners_.end(), [](const auto& l) { return !l->idle(); });
  if (u.all) {
    for (std::size_t i = 0; i < table_->bodies.size(); ++i) saveUndoOf(i);
  } else {
    refreshAwake();
    for (const std::uint32_t i : awakeList_) saveUndoOf(i);
  }
  undoOpen_ = !u.all;
  // Pose events are erased as they are applied: kept only when one is due this step.
  u.eventsSaved = !pendingEvents_.empty() && pendingEvents_.front().time <= time();
  if (u.eventsSaved) u.events = pendingEvents_;
  u.stepCount = stepCount_;
}

void World::saveUndoOf(std::size_t i) {
  StepUndo& u = undo_;
  const RigidBody& body = table_->bodies[i];
  u.index.push_back(static_cast<std::uint32_t>(i));
  u.states.push_back(body.state());
  u.awake.push_back(body.awake() ? 1 : 0);
  u.resting.push_back(body.restingTime());
  u.force.push_back(body.force());
  u.torque.push_back(body.torque());
  u.bodyTorque.push_back(body.bodyTorque());
  if (settings_.integrator == Integrator::EulerMatrix && !settings_.driftCorrection) u.rotations.push_back(body.rotation());
}

void World::undoStep() {
  const StepUndo& u = undo_;
  // The bodies are those saved: the stages after SpawnAndRemove add and remove none. Latest saved
  // first, so that a body saved twice (asleep, woken, asleep and woken again) ends as it began.
  for (std::size_t k = u.index.size(); k-- > 0;) {
    if (u.index[k] >= table_->bodies.size()) continue;
    RigidBody& body = table_->bodies[u.index[k]];
    if (k < u.rotations.size()) {
      body.setState(u.states[k], u.rotations[k]);
    } else {
      body.setState(u.states[k]);
    }
    if (u.awake[k] != 0) {
      body.wake();
    } else if (!body.isStatic()) {
      body.sleep();  // P = L = 0, as they were saved
    }
    body.setRestingTime(u.resting[k]);
    body.clearAccumulators();
    body.applyForce(u.force[k]);
    body.applyTorque(u.torque[k]);
    body.applyBodyTorque(u.bodyTorque[k]);
  }
  if (u.eventsSaved) pendingEvents_ = u.events;
  stepCount_ = u.stepCount;
  ++geometryVersion_;
  awakeStale_ = true;
}

void World::saveSpawns() {
  StepUndo& u = undo_;
  u.spawnsSaved = true;
  u.bodyCount = table_->bodies.size();
  u.slots = table_->ids.slots();
  u.freeSlot = table_->ids.freeSlot();
  u.shapeIds = table_->shapeIds;
  u.spawners = spawners_;
  u.spawned = spawnedNow_;
  u.removed = removedNow_;
}

void World::undoSpawns() {
  StepUndo& u = undo_;
  // The step removed nothing, so the bodies it made are those past the count before it, and
  // destroyBodies pops them off the ends of every per-body array with their joints; the ids'
  // table then goes back to what it was, the generations those slots moved on to included.
  std::vector<BodyId> made;
  for (std::size_t i = u.bodyCount; i < table_->bodies.size(); ++i) made.push_back(idAt(i));
  destroyBodies(made);
  // The bodies it made are gone, so the table's items are those before it, each in its slot.
  table_->ids.assign(u.slots, table_->ids.slotOfItem(), u.freeSlot);
  table_->shapeIds = u.shapeIds;
  spawners_ = u.spawners;
  spawnedNow_ = u.spawned;
  removedNow_ = u.removed;
}

void World::restoreWhole(World&& before) noexcept {
  // The listeners stay the caller's own objects (addStepListener returned references to them);
  // the copy holds clones.
  std::vector<std::unique_ptr<StepListener>> listeners = std::move(listeners_);
  *this = std::move(before);
  listeners_ = std::move(listeners);
}

}  // namespace rbsim
