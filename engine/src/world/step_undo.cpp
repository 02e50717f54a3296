// A failed step is undone (issue 56, item 6; the brief: "a failed step leaves the World as it
// was"): a step that removes bodies from a copy of the whole World (World::step), one that only
// spawns by removing what it made (undoSpawns), and every step as follows. Before the stages
// that can fail, World::step keeps what they change that a retry reads, in arrays reused from
// step to step (O(bodies) copies, about 0.1 ms for 5050 bodies against the step's 100 ms, and no
// allocation once the World has stopped growing).
#include <utility>
#include <vector>

#include "rbsim/world/world.h"

namespace rbsim {

void World::saveUndo() {
  StepUndo& u = undo_;
  const std::size_t n = bodies_.size();
  const bool rawMatrix = settings_.integrator == Integrator::EulerMatrix && !settings_.driftCorrection;
  u.states.resize(n);
  u.awake.resize(n);
  u.resting.resize(n);
  u.force.resize(n);
  u.torque.resize(n);
  u.bodyTorque.resize(n);
  u.rotations.resize(rawMatrix ? n : 0);
  for (std::size_t i = 0; i < n; ++i) {
    const RigidBody& body = bodies_[i];
    u.states[i] = body.state();
    u.awake[i] = body.awake() ? 1 : 0;
    u.resting[i] = body.restingTime();
    u.force[i] = body.force();
    u.torque[i] = body.torque();
    u.bodyTorque[i] = body.bodyTorque();
    if (rawMatrix) u.rotations[i] = body.rotation();
  }
  // Pose events are erased as they are applied: kept only when one is due this step.
  u.eventsSaved = !pendingEvents_.empty() && pendingEvents_.front().time <= time();
  if (u.eventsSaved) u.events = pendingEvents_;
  u.stepCount = stepCount_;
}

void World::undoStep() {
  const StepUndo& u = undo_;
  // The bodies are those saved: the stages after SpawnAndRemove add and remove none.
  for (std::size_t i = 0; i < bodies_.size() && i < u.states.size(); ++i) {
    RigidBody& body = bodies_[i];
    if (i < u.rotations.size()) {
      body.setState(u.states[i], u.rotations[i]);
    } else {
      body.setState(u.states[i]);
    }
    if (u.awake[i] != 0) {
      body.wake();
    } else if (!body.isStatic()) {
      body.sleep();  // P = L = 0, as they were saved
    }
    body.setRestingTime(u.resting[i]);
    body.clearAccumulators();
    body.applyForce(u.force[i]);
    body.applyTorque(u.torque[i]);
    body.applyBodyTorque(u.bodyTorque[i]);
  }
  if (u.eventsSaved) pendingEvents_ = u.events;
  stepCount_ = u.stepCount;
  ++geometryVersion_;
}

void World::saveSpawns() {
  StepUndo& u = undo_;
  u.spawnsSaved = true;
  u.bodyCount = bodies_.size();
  u.slots = slots_;
  u.freeSlot = freeSlot_;
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
  for (std::size_t i = u.bodyCount; i < bodies_.size(); ++i) made.push_back(idAt(i));
  destroyBodies(made);
  slots_ = u.slots;
  freeSlot_ = u.freeSlot;
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
