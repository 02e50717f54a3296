#pragma once
// The World owns the bodies and advances them; step() reads as the pipeline (docs/architecture.md,
// "The step"), one named stage per call, each skipped when the scene has nothing for it.
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/contact.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/dynamics/solved_contact_point.h"
#include "rbsim/body/material.h"
#include "rbsim/dynamics/step_listener.h"
#include "rbsim/body/body_id.h"
#include "rbsim/world/contact_events.h"
#include "rbsim/body/id_table.h"
#include "rbsim/world/item_ids.h"
#include "rbsim/world/kinematic_motion.h"
#include "rbsim/world/query_cache.h"
#include "rbsim/world/scripts.h"
#include "rbsim/world/body_table.h"
#include "rbsim/world/shape_table.h"
#include "rbsim/world/spawner.h"
#include "rbsim/world/spring.h"
#include "rbsim/settings/settings.h"

namespace rbsim {

struct FracturePattern;    // fracture/fracture.h: a body's pieces, kept per body
class BodyRemoval;         // a batch of removals (engine/src/body/body_removal.h)
class CollisionPipeline;   // the collision stages (engine/src/world/collision_pipeline.h)
class ContactSolver;       // the contact solver's seam (engine/src/dynamics/contact_solver.h)
class ContactEventTracker;  // contact events step to step (engine/src/world/contact_event_tracker.h)
struct WorldAccess;        // the internals tests read (engine/src/world/world_access.h)

// Stages of World::step, in order (as Box2D v3's b2SolverStageType): names for timing and for
// skipping.
enum class Stage : int {
  SpawnAndRemove,    // bodies that left the kill volume are removed, spawners' due bursts added
                     // (world/spawner.h); skipped when there are neither
  ApplyPoseEvents,   // manual sets of x, R, v, omega due at this step, and the velocities of
                     // kinematic bodies on a prescribed motion (world/kinematic_motion.h)
  AccumulateForces,  // scripted forces and springs (and gravity, when they act) into F and tau
  Integrate,         // the chosen integrator advances awake bodies (adding gravity when no other
                     // force acts), with soft step only those the solver did not; accumulators
                     // are cleared
  ContinuousCollision,  // fast bodies stop at their time of impact instead of tunnelling
  BroadPhase,        // sweep and prune over world AABBs: candidate pairs
  NarrowPhase,       // contact manifolds of candidate pairs and of bodies against planes
  SolveContacts,     // soft step: substeps advancing the bodies in contact; PGS: impulses on the
                     // integrated bodies and a split-impulse correction
  BreakBodies,       // bodies whose contact impulses this step exceed their fracture threshold
                     // break into their pieces (seed 000 "Fracture"); skipped when none can
  UpdateSleep,       // islands of touching bodies, all slow for Settings::timeToSleep, fall asleep
  StepSystems,       // the step hook: systems beside the rigid bodies (particles, soft bodies,
                     // the 2D world; world/systems.h), in the order added; skipped when all idle
  Count
};
const char* stageName(Stage stage);

// A body that broke: it became its first piece, and the others were added as new bodies.
struct FractureEvent {
  double time = 0.0;            // [s]
  BodyId body;                  // the body that broke, now its first piece (same id)
  std::vector<BodyId> added;    // the other pieces, new bodies
  double impulse = 0.0;         // the normal impulses that broke it [N s]
};

struct StageStats {
  std::uint64_t runs = 0;     // steps in which the stage ran
  std::uint64_t skipped = 0;  // steps in which it had nothing to do
  double seconds = 0.0;       // wall time spent in it and in the step's checks before it [s]
};

// World is a conductor (issue 58; docs/architecture.md, "The World's surface"): the class holds
// the core (bodies and ids, the step, settings, planes, joints, scripted forces, pose events, the
// step hook, the last step's contacts), and what grows beside it is a free function over World in
// a header of its own (world/spawner.h, kinematic_motion.h, ragdoll.h, spring.h, body_changes.h,
// joint_changes.h, contact_events.h, queries.h), reaching the members through WorldAccess. At most
// 35 public member functions, counted by tests/layers/check_world_api.py (ctest world_api): every
// public member function declaration once, constructors, the destructor and the assignments
// included, each overload on its own; 33 now.
class World {
  friend struct WorldAccess;  // world/world_access.h: the free functions' and tests' way in
  friend struct WorldSnapshotAccess;  // world/world_snapshot.cpp: writes and reads every member

 public:
  explicit World(const Settings& settings);  // throws std::invalid_argument (checkSettings)
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  // A deep copy that goes on alone: bodies, ids, contacts, the solver's warm starts, sleep timers
  // and the step systems. Stepping the copy gives bit for bit what stepping the original would
  // (a saved state, as Jolt's PhysicsSystem::SaveState and MuJoCo's mj_copyData). Throws
  // std::invalid_argument for a World with a step listener that cannot be copied
  // (StepListener::clone).
  World(const World& other);
  World& operator=(const World& other);

  // Throws std::invalid_argument on an invalid def, naming the body (also for a fracture pattern
  // that does not fit it: fracture/fracture.h checkFracturePattern). The new body is the last of
  // bodies(); its id stays valid until it is destroyed, whatever else is added or destroyed.
  BodyId addBody(const BodyDef& def);
  // Removes the body and what acts on it alone (its scripted forces, springs, pose events and
  // joints) and wakes the bodies touching it; the last body takes its index (bodies() stays
  // dense), its id unchanged. The other contacts take their bodies' new indices; pairs and warm
  // starts are keyed by the bodies' slots, which stay (dynamics/contact_key.h pairKey), so none is
  // renamed or turned round. Throws std::invalid_argument on a stale id.
  void destroyBody(BodyId id);
  // Destroys the bodies in the order given, leaving the World exactly as destroyBody on each in
  // turn would (the same indices, ids, contacts and warm starts), in one pass over what names
  // bodies: the ids, the bodies they reach (removed or moved) and the sleeping contacts those
  // hold, plus one pass over the awake bodies' contacts and the joints, for the whole batch (a
  // resting pile of 10,000 costs what one of 1,000 does: docs/speed.md). Throws
  // std::invalid_argument, destroying none, on a stale or repeated id.
  void destroyBodies(const std::vector<BodyId>& ids);
  bool isValid(BodyId id) const;
  // The body's index in bodies() now; throws std::invalid_argument on a stale id.
  std::size_t indexOf(BodyId id) const;
  BodyId idAt(std::size_t index) const;  // the id of bodies()[index]; throws when out of range
  // Manual changes go through here (seed 004's "change x and R"): bodies() is read-only, since
  // adding or removing bodies behind the World's back would leave its per-body data behind.
  // Handing a body out for change counts as a change of the geometry (geometryVersion): change it
  // through a fresh body(id) after a query, not through a reference kept from before.
  RigidBody& body(BodyId id) {
    ++geometryVersion_;
    const std::size_t index = indexOf(id);
    listAwake(index);  // it may be woken through the reference: the next step looks at it
    return table_->bodies[index];
  }
  const RigidBody& body(BodyId id) const { return table_->bodies[indexOf(id)]; }
  void addForce(const ScriptedForce& force);
  void addPoseEvent(const PoseEvent& event);
  // Static and infinite; throws unless the normal is unit and the material valid.
  void addPlane(const Plane& plane, const Material& material = {});
  // The step hook (Jolt's PhysicsStepListener): a system stepped after the rigid bodies each
  // step, in the order added (stage StepSystems). world/systems.h adds particles, soft bodies and
  // the 2D world this way.
  StepListener& addStepListener(std::unique_ptr<StepListener> listener);
  const std::vector<std::unique_ptr<StepListener>>& stepListeners() const { return listeners_; }
  // A ball or hinge joint between def.bodyA (dynamic) and def.bodyB (any body, or kWorldAnchor)
  // at the bodies' poses now (world/joints.cpp). Throws std::invalid_argument on a bad def, and
  // under the PGS solver, which does not solve joints. Returns its id (world/item_ids.h).
  JointId addJoint(const JointDef& def);
  const std::vector<Joint>& joints() const { return joints_; }
  // A joint's id and its index in joints(): isValid, indexOf and jointIdAt in world/joint_changes.h.


  // Advances by settings().timeStep. Throws SimulationError if a body's state stops being finite,
  // and StepLimitError (a SimulationError) when the bodies overlap in more pairs or contacts than
  // a step holds (kMaxBroadPhasePairs), before they are listed. A step that throws is undone
  // (issue 56, item 6; world/step_undo.cpp): every body's state, sleep, resting time and applied
  // forces, the pending pose events and the step count are as before it, so step() may be called
  // again after the cause is fixed. A step whose first stage spawns or removes bodies is undone
  // from a copy of the whole World made before it: the bodies, ids, names, joints and spawners
  // are as before too. One thing stays: on a step that spawns and removes nothing, the warm
  // starts the contact and joint caches kept from the failed attempt.
  void step();
  // Puts the World where a recording saw it (app/record; Jolt's PhysicsSystem::RestoreState):
  // at step `stepCount`, every body in `states` with its awake flag, nothing simulated. Contacts
  // and the solvers' warm starts are left as they were. Throws std::invalid_argument when the
  // sizes do not match the bodies.
  void restore(std::uint64_t stepCount, const std::vector<BodyState>& states, const std::vector<char>& awake);

  const Settings& settings() const { return settings_; }
  // Changes the settings of a running World (Jolt's PhysicsSystem::SetPhysicsSettings): checked
  // as a scene's (checkSettings), std::invalid_argument otherwise, and then also when it changes
  // the broad phase method (its proxies are built for one) or asks for the PGS solver with joints
  // (it solves none). A new solver starts without warm starts. A new time step counts from now:
  // time() goes on from where it is.
  void setSettings(const Settings& settings);
  // The time step changes only through setSettings, so time() is the time when it last changed
  // plus the steps since at the current step (both 0 before: stepCount x dt, as always).
  double time() const {
    return timeOrigin_ + static_cast<double>(stepCount_ - stepsAtOrigin_) * settings_.timeStep;
  }
  std::uint64_t stepCount() const { return stepCount_; }
  const std::vector<RigidBody>& bodies() const { return table_->bodies; }
  const std::vector<Plane>& planes() const { return planes_; }
  // The contact manifolds of the last narrow phase, and every contact point of the last step
  // with the impulse the solver gave it. contacts() lists the step's (those of awake bodies, then
  // those of islands the step woke), then the contacts sleeping islands keep from the step they
  // fell asleep in, ordered by (kind, a, b, part, children); the sleeping ones are gathered when
  // asked, not by the step (issue 58). contactPoints() index the first part: an island's contacts
  // go aside in the step it falls asleep, and their points leave the report with them.
  const std::vector<Contact>& contacts() const;
  const std::vector<SolvedContactPoint>& contactPoints() const;
  const StageStats& stageStats(Stage stage) const { return stats_[static_cast<int>(stage)]; }

  // FNV-1a over the bit patterns of every body's state, then of each step listener's (particles,
  // soft nodes, 2D bodies; nothing when there are none): equal hashes mean identical runs.
  std::uint64_t stateHash() const;

 private:
  void applyPoseEvents();
  void driveKinematicBodies();  // world/kinematic_motion.cpp
  void spawnAndRemove();        // world/spawning.cpp
  bool spawnDue() const;    // whether this step's spawnAndRemove will add a body
  bool removalDue() const;  // whether it will remove one
  bool outsideKillVolume(std::size_t i) const;  // body i is taken by the kill volume
  double spawnDueTime() const;  // bursts and ages up to this time [s] happen at this step
  void accumulateForces(bool withGravity);  // scripted forces and springs, after gravity if asked
  void integrateBodies(bool withGravity);   // adds m g to F first if asked
  // The middle of step() in the solver's order (ContactSolver::Order).
  void stepCollideFirst(bool withGravity, bool awake, bool collides);
  void stepIntegrateFirst(bool withGravity, bool awake, bool collides);
  void solveContacts(bool withGravity);
  void wakeTouchedIslands();  // a sleeping island touched by an awake body wakes whole
  void wakeJointed();         // a joint's sleeping side wakes with its awake one
  template <typename T>
  void removeStale(std::vector<T>& items) const;  // the entries whose `body` id is no longer valid
  void updateJointFilter();   // the pairs that must not collide, after joints or indices changed
  void checkFinite(const std::vector<std::size_t>& bodies) const;  // after a solver advanced them
  void updateSleep();                  // world/awake_bodies.cpp, with the six below
  void sleepContacts();                // the contacts of islands that fell asleep go aside now
  void refreshAwake();                 // awakeList_ is the awake bodies, in index order
  void rebuildAwake();                 // ... from a scan of every body (after removals, loads, undo)
  void wakeBody(std::size_t index);    // wakes and lists it
  void renumberAwake(const BodyRemoval& removal);  // world/bodies.cpp: the list after a removal
  // Sleeping islands with a body awake now wake whole (Box2D's b2WakeSolverSet): their kept
  // contacts go back to the solver and the event tracker; `solveNow`: appended to this step's
  // contacts (the narrow phase has run), else dropped (it collides them afresh).
  void wakeIslandsOf(const std::vector<std::size_t>& seeds, bool solveNow);
  void wakeListedIslands();            // before the collision stages: islands of bodies woken since
  void listAwake(std::size_t index) {  // body(id)'s and every wake's: the next pass visits it
    if (table_->listed[index] != 0) return;
    if (undoOpen_) saveUndoOf(index);  // before the step changes it
    table_->listed[index] = 1;
    if (!awakeList_.empty() && awakeList_.back() > index) awakeSorted_ = false;
    awakeList_.push_back(static_cast<std::uint32_t>(index));
  }
  void breakBodies();  // world/break_bodies.cpp
  void breakBody(std::size_t body, double impulse);
  [[noreturn]] void reportDivergence(const RigidBody& body, const BodyState& next) const;

  template <typename Fn>
  bool runStage(Stage stage, bool needed, Fn&& fn);  // true when it ran
  void advance();     // step()'s stages after SpawnAndRemove
  void saveUndo();    // what a failed step puts back (world/step_undo.cpp)
  void saveUndoOf(std::size_t index);  // one body's part of it
  void undoStep();    // puts it back; never throws
  void restoreWhole(World&& before) noexcept;  // a copy from before a step that removed bodies
  void saveSpawns();  // before a step that only spawns: what undoSpawns puts back
  void undoSpawns();  // removes the bodies the step made

  Settings settings_;
  // Every per-body column and the ids that name the rows (world/body_table.h), on the heap so
  // that the collision pipeline, which reads and writes its own columns there, keeps its address
  // when the World moves.
  std::unique_ptr<BodyTable> table_;
  // Per body index, its stable key (its slot): what pairs and warm starts are named by, so that a
  // removal, which moves bodies to new indices, renames none of them.
  const std::vector<std::uint32_t>& bodyKeys() const { return table_->keys(); }
  std::vector<ScriptedForce> forces_;
  std::vector<Spring> springs_;
  IdTable<SpringId> springIds_;  // springs_'s ids (world/spring.h)
  std::vector<Plane> planes_;
  std::vector<Material> planeMaterials_;  // per plane
  std::vector<std::unique_ptr<StepListener>> listeners_;
  std::size_t breakableBodies_ = 0;      // bodies with a pattern that have not broken yet
  std::vector<double> receivedImpulse_;  // BreakBodies' scratch, per body [N s]
  std::vector<FractureEvent> fractureEvents_;
  std::unique_ptr<CollisionPipeline> collision_;
  std::unique_ptr<ContactSolver> solver_;  // Settings::solver's
  std::unique_ptr<ContactEventTracker> contactEvents_;  // never null but in a moved-from World
  std::vector<double> islandRestingTime_;  // UpdateSleep's scratch, per island root [s]
  // The awake bodies (issue 58, "no scan of every body"; Box2D's awake solver set): every awake
  // body's index, plus those body(id) handed out or a stage woke since the last refreshAwake();
  // every per-step pass visits these alone. The table's listed column: in awakeList_. awakeStale_: the
  // indices changed (removal, a load, an undo): rebuilt from a scan before the next step.
  std::vector<std::uint32_t> awakeList_;
  bool awakeSorted_ = true;
  bool awakeStale_ = true;
  std::size_t awakeScanned_ = 0;  // bodies refreshAwake has looked at; those past it are new
  std::vector<std::uint32_t> localIndex_;  // UpdateSleep's scratch, per body: its place in awakeList_
  bool undoOpen_ = false;  // in a step, after saveUndo: a body listed now is saved first
  std::vector<Joint> joints_;
  IdTable<JointId> jointIds_;  // joints_'s ids
  std::vector<PoseEvent> pendingEvents_;  // sorted by time; applied ones are removed
  std::vector<KinematicMotion> motions_;  // at most one per body
  std::vector<Spawner> spawners_;
  Aabb killVolume_;                    // empty: none
  std::vector<BodyId> spawnedNow_, removedNow_;  // stage SpawnAndRemove's, last step
  std::uint64_t stepCount_ = 0;
  std::uint64_t geometryVersion_ = 0;
  QueryCacheSlot queryCache_;          // world/world_queries.h's tree; a copy starts without
  double timeOrigin_ = 0.0;            // time() when the time step last changed [s]
  std::uint64_t stepsAtOrigin_ = 0;    // stepCount_ then
  std::array<StageStats, static_cast<int>(Stage::Count)> stats_{};
  // A step's undo record, kept between steps so that it allocates only as the World grows.
  struct StepUndo {
    // Per saved body (the awake ones, and those the step wakes; every body when a step listener
    // runs, which may wake any): its index, then what it was.
    bool all = false;
    std::vector<std::uint32_t> index;
    std::vector<BodyState> states;
    std::vector<Mat3> rotations;  // euler-matrix without drift correction keeps R apart from q
    std::vector<char> awake;
    std::vector<double> resting;        // [s]
    std::vector<Vec3> force, torque, bodyTorque;  // the accumulators [N, N m, N m]
    std::vector<PoseEvent> events;      // pendingEvents_, when some are due
    bool eventsSaved = false;
    std::uint64_t stepCount = 0;
    // A step that only spawns (saveSpawns): the bodies before it, the ids' tables, the spawners
    // and the last step's lists of made and removed bodies.
    bool spawnsSaved = false;
    std::size_t bodyCount = 0;
    std::vector<IdTable<BodyId>::Slot> slots;
    std::uint32_t freeSlot = UINT32_MAX;
    ShapeTable shapeIds;
    std::vector<Spawner> spawners;
    std::vector<BodyId> spawned, removed;
  } undo_;
  std::chrono::steady_clock::time_point stageClock_;  // when the running stage's time began
};

// Defined here, not in world.cpp: the contact stages (contact_stages.cpp) run stages too.
template <typename Fn>
inline bool World::runStage(Stage stage, bool needed, Fn&& fn) {
  StageStats& stats = stats_[static_cast<int>(stage)];
  if (!needed && settings_.skipIdleStages) {
    ++stats.skipped;
    return false;
  }
  fn();
  // One clock read per stage run, each stage's end starting the next one's time: with one body,
  // two reads per stage took a third of the step.
  const auto end = std::chrono::steady_clock::now();
  stats.seconds += std::chrono::duration<double>(end - stageClock_).count();
  stageClock_ = end;
  ++stats.runs;
  return true;
}

}  // namespace rbsim
