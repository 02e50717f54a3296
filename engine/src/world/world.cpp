#include "rbsim/world/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "body/step_prefetch.h"
#include "dynamics/contact_solver.h"
#include "rbsim/integrate/integrator.h"
#include "math/fnv.h"
#include "rbsim/fracture/fracture.h"
#include "world/collision_pipeline.h"
#include "world/contact_event_tracker.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim {

namespace {

// The Integrate pass over many bodies, tuned with bench/throughput_bench. Bodies are stepped in
// batches: first the integrator step of every body in the batch, then every body's derived
// quantities. One body at a time, each waited on its own chain of dependent square roots and
// divisions; within a phase the bodies are independent, so the processor overlaps their chains
// (1e3 bodies in cache: euler-quat 23 -> 28, expmap 15 -> 21 million body-steps/s). Each body's
// lines are asked for kPrefetchAhead bodies before it is stepped, which the hardware prefetcher
// alone did not do in time (1e5 bodies: euler-quat 10 -> 16 million/s); 4, 8 and 16 ahead
// measured alike.
constexpr std::size_t kIntegrateBatch = 8;
constexpr std::size_t kPrefetchAhead = 8;

}  // namespace

const char* stageName(Stage stage) {
  switch (stage) {
    case Stage::SpawnAndRemove: return "spawn-and-remove";
    case Stage::ApplyPoseEvents: return "apply-pose-events";
    case Stage::AccumulateForces: return "accumulate-forces";
    case Stage::Integrate: return "integrate";
    case Stage::ContinuousCollision: return "continuous-collision";
    case Stage::BroadPhase: return "broad-phase";
    case Stage::NarrowPhase: return "narrow-phase";
    case Stage::SolveContacts: return "solve-contacts";
    case Stage::BreakBodies: return "break-bodies";
    case Stage::UpdateSleep: return "update-sleep";
    case Stage::StepSystems: return "step-systems";
    case Stage::Count: break;
  }
  return "unknown";
}

namespace {
const Settings& checked(const Settings& settings) {
  const SettingsProblem problem = checkSettings(settings);
  if (problem) throw std::invalid_argument(problem.message());
  return settings;
}
}  // namespace

World::World(const Settings& settings)
    : settings_(checked(settings)),
      table_(std::make_unique<BodyTable>()),
      collision_(std::make_unique<CollisionPipeline>(settings_, *table_)),
      solver_(makeContactSolver(settings_.solver)),
      contactEvents_(std::make_unique<ContactEventTracker>()) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

namespace {
std::vector<std::unique_ptr<StepListener>> cloned(const std::vector<std::unique_ptr<StepListener>>& listeners) {
  std::vector<std::unique_ptr<StepListener>> copies;
  for (const std::unique_ptr<StepListener>& listener : listeners) {
    copies.push_back(listener->clone());
    if (!copies.back()) throw std::invalid_argument("World: a step listener that cannot be copied (StepListener::clone)");
  }
  return copies;
}
}  // namespace

// Every member of World, in the order world.h declares them: the three owned polymorphic parts
// are cloned, the step listeners through StepListener::clone, the rest are values (shapes, grids
// and fracture patterns are shared, immutable).
//
// sizeof(World) is checked so that a member added to world.h cannot be forgotten here. If this
// fails: copy the new member below (or say below why a copy starts without it, as the query
// cache and the undo record do), write and read it in the snapshot (world_snapshot.cpp, which
// checks the same figure), then set the figure here and there to the new sizeof(World). The 4
// bytes of padding after the ids' free list head are inside IdTable, where no member can hide.
// Checked where the standard library lays out vectors in 3 pointers of 8 bytes (libstdc++, libc++
// and MSVC's release library on every 64-bit target the engine builds for, docs/ci.md).
constexpr std::size_t kWorldBytesCopied = 1584;
static_assert(sizeof(void*) != 8 || sizeof(std::vector<char>) != 24 || sizeof(World) == kWorldBytesCopied,
              "a member was added to or removed from World: see the comment above World's copy constructor");
World::World(const World& other)
    : settings_(other.settings_),
      table_(std::make_unique<BodyTable>(*other.table_)),
      forces_(other.forces_),
      springs_(other.springs_),
      springIds_(other.springIds_),
      planes_(other.planes_),
      planeMaterials_(other.planeMaterials_),
      listeners_(cloned(other.listeners_)),
      breakableBodies_(other.breakableBodies_),
      receivedImpulse_(other.receivedImpulse_),
      fractureEvents_(other.fractureEvents_),
      collision_(std::make_unique<CollisionPipeline>(*other.collision_, *table_)),
      solver_(other.solver_->clone()),
      contactEvents_(std::make_unique<ContactEventTracker>(*other.contactEvents_)),
      islandRestingTime_(other.islandRestingTime_),
      awakeList_(other.awakeList_),
      awakeSorted_(other.awakeSorted_),
      awakeStale_(other.awakeStale_),
      awakeScanned_(other.awakeScanned_),
      localIndex_(),      // UpdateSleep's scratch, filled afresh by the next step
      undoOpen_(false),   // true only inside a step
      joints_(other.joints_),
      jointIds_(other.jointIds_),
      pendingEvents_(other.pendingEvents_),
      motions_(other.motions_),
      spawners_(other.spawners_),
      killVolume_(other.killVolume_),
      spawnedNow_(other.spawnedNow_),
      removedNow_(other.removedNow_),
      stepCount_(other.stepCount_),
      geometryVersion_(other.geometryVersion_),
      queryCache_(),  // the copy builds its own query tree on its first query (world_queries.h)
      timeOrigin_(other.timeOrigin_),
      stepsAtOrigin_(other.stepsAtOrigin_),
      stats_(other.stats_),
      undo_(),  // a step's scratch, filled afresh by the next step (step_undo.cpp)
      stageClock_(other.stageClock_) {}

World& World::operator=(const World& other) {
  if (this != &other) *this = World(other);
  return *this;
}

void World::setSettings(const Settings& settings) {
  checked(settings);
  ++geometryVersion_;
  if (settings.broadPhase != settings_.broadPhase) {
    throw std::invalid_argument("the broad phase method cannot change on a running World (its proxies are built for one)");
  }
  std::unique_ptr<ContactSolver> solver;
  if (settings.solver != settings_.solver) {
    solver = makeContactSolver(settings.solver);
    if (!joints_.empty() && !solver->solvesJoints()) {
      const std::string which = settings.solver == Settings::ContactSolverMethod::Pgs ? "PGS" : "LCP";
      throw std::invalid_argument("the World has " + std::to_string(joints_.size()) + " joints, and the " + which +
                                  " solver solves none (keep the soft-step solver)");
    }
    // A ragdoll spawner's later bursts need joints too (addSpawner refuses one under PGS): the
    // switch would leave them to fail in the middle of a step (issue 56, item 6).
    const auto ragdolls = std::find_if(spawners_.begin(), spawners_.end(), [](const Spawner& s) { return s.def.ragdoll.has_value(); });
    if (ragdolls != spawners_.end() && !solver->solvesJoints()) {
      const std::string which = settings.solver == Settings::ContactSolverMethod::Pgs ? "PGS" : "LCP";
      throw std::invalid_argument("the spawner '" + ragdolls->def.name + "' makes ragdolls, whose joints the " + which +
                                  " solver does not solve (keep the soft-step solver)");
    }
  }
  for (const Spawner& spawner : spawners_) {
    const std::string problem = checkSpawnPeriod(spawner.def.period, settings.timeStep);
    if (!problem.empty()) throw std::invalid_argument("spawner '" + spawner.def.name + "': " + problem);
  }
  if (settings.timeStep != settings_.timeStep) {
    timeOrigin_ = time();
    stepsAtOrigin_ = stepCount_;
  }
  settings_ = settings;
  collision_->setSettings(settings_);
  if (solver) solver_ = std::move(solver);
}

const std::vector<Contact>& World::contacts() const { return collision_->reported(); }
const std::vector<SolvedContactPoint>& World::contactPoints() const { return solver_->points(); }

void World::addForce(const ScriptedForce& force) {
  if (!isValid(force.body)) throw std::invalid_argument("scripted force names no body");
  forces_.push_back(force);
}

void World::addPlane(const Plane& plane, const Material& material) {
  if (!plane.normal.allFinite() || !std::isfinite(plane.offset) || std::abs(plane.normal.norm() - 1.0) > 1e-9) {
    throw std::invalid_argument("plane: expected a finite unit normal and a finite offset");
  }
  const std::string problem = checkMaterial(material);
  if (!problem.empty()) throw std::invalid_argument("plane: " + problem);
  planes_.push_back(plane);
  planeMaterials_.push_back(material);
}

StepListener& World::addStepListener(std::unique_ptr<StepListener> listener) {
  if (!listener) throw std::invalid_argument("addStepListener: no listener");
  listeners_.push_back(std::move(listener));
  return *listeners_.back();
}

void World::addPoseEvent(const PoseEvent& event) {
  if (!isValid(event.body)) throw std::invalid_argument("pose event names no body");
  const auto at = std::upper_bound(pendingEvents_.begin(), pendingEvents_.end(), event,
                                   [](const PoseEvent& a, const PoseEvent& b) { return a.time < b.time; });
  pendingEvents_.insert(at, event);
}


void World::step() {
  ++geometryVersion_;  // the bodies move, appear and go (world_queries.h rebuilds its tree)
  stageClock_ = std::chrono::steady_clock::now();
  // A step whose first stage removes bodies is undone from a copy of the whole World made before
  // it, which only such steps pay for; one that only spawns by removing what it made (a copy cost
  // Box3D's large_world, 100 bursts onto 10,000 static boxes, 45 % of its run); any other from the
  // undo record alone (world/step_undo.cpp).
  const bool staged = !spawners_.empty() || !killVolume_.empty();
  std::optional<World> before;
  undo_.spawnsSaved = false;
  if (staged && removalDue()) {
    before.emplace(*this);
  } else if (staged && spawnDue()) {
    saveSpawns();
  }
  spawnedNow_.clear();
  removedNow_.clear();
  contactEvents_->beginStep();
  bool saved = false;
  try {
    runStage(Stage::SpawnAndRemove, !spawners_.empty() || !killVolume_.empty(), [&] { spawnAndRemove(); });
    saveUndo();
    saved = true;
    advance();
    undoOpen_ = false;
    contactEvents_->commit();
  } catch (...) {
    undoOpen_ = false;
    if (before) {
      restoreWhole(std::move(*before));
    } else {
      if (saved) undoStep();
      if (undo_.spawnsSaved) undoSpawns();
    }
    throw;
  }
}

void World::advance() {
  const double t = time();
  refreshAwake();
  const bool anyAwake = !awakeList_.empty();
  const std::uint64_t solveRunsBefore = stats_[static_cast<int>(Stage::SolveContacts)].runs;
  const bool anyForce = std::any_of(forces_.begin(), forces_.end(), [t](const ScriptedForce& f) { return isActive(f, t); });
  const bool posed = runStage(Stage::ApplyPoseEvents,
                              !motions_.empty() || (!pendingEvents_.empty() && pendingEvents_.front().time <= t), [&] {
                                applyPoseEvents();
                                driveKinematicBodies();
                              });
  // Gravity acts on every awake body; the Integrate pass adds it itself, sparing a pass over all
  // bodies, unless scripted forces or springs act: then AccumulateForces adds it before them, so
  // that F sums in the order it always has (and the result is bit for bit the same).
  const bool otherForces = anyForce || (anyAwake && !springs_.empty());
  const bool pushed = runStage(Stage::AccumulateForces, otherForces, [&] { accumulateForces(otherForces); });
  // Pose events and forces may have woken bodies; only then is a second pass over them needed.
  if (posed || pushed) refreshAwake();
  const bool anyAwakeNow = !awakeList_.empty();
  wakeListedIslands();
  const bool collides = settings_.detectCollisions && (!planes_.empty() || table_->bodies.size() >= 2);
  try {
    if (solver_->order() == ContactSolver::Order::IntegrateFirst) {
      stepIntegrateFirst(!otherForces, anyAwakeNow, collides);
    } else {
      stepCollideFirst(!otherForces, anyAwakeNow, collides);
    }
  } catch (const StepLimitError& e) {
    std::ostringstream when;
    when << "step " << stepCount_ << " (t = " << t << " s): " << e.what();
    throw StepLimitError(when.str());
  }
  const bool solved = stats_[static_cast<int>(Stage::SolveContacts)].runs > solveRunsBefore;
  runStage(Stage::BreakBodies, breakableBodies_ > 0 && solved && settings_.respondToContacts, [&] {
    if (breakableBodies_ > 0 && solved && settings_.respondToContacts) breakBodies();
  });
  runStage(Stage::UpdateSleep, settings_.allowSleep && anyAwakeNow, [&] { updateSleep(); });
  const bool systemsBusy = std::any_of(listeners_.begin(), listeners_.end(), [](const auto& l) { return !l->idle(); });
  runStage(Stage::StepSystems, systemsBusy, [&] {
    const StepContext context{t, stepCount_, settings_, table_->bodies, table_->solids, table_->materials, planes_, planeMaterials_};
    for (const std::unique_ptr<StepListener>& listener : listeners_) listener->step(context);
    awakeStale_ = true;  // a listener may wake bodies (soft contacts do), unseen by listAwake
  });
  ++stepCount_;
}

void World::applyPoseEvents() {
  const double t = time();
  auto due = pendingEvents_.begin();
  for (; due != pendingEvents_.end() && due->time <= t; ++due) {
    RigidBody& body = this->body(due->body);
    if (due->position) body.setPosition(*due->position);
    if (due->orientation) body.setOrientation(*due->orientation);
    if (due->velocity) body.setVelocity(*due->velocity);
    if (due->angularVelocity) body.setAngularVelocity(*due->angularVelocity);
    body.wake();  // an event setting nothing still marks the body as touched
  }
  pendingEvents_.erase(pendingEvents_.begin(), due);
}

void World::accumulateForces(bool withGravity) {
  const double t = time();
  for (const ScriptedForce& f : forces_) {
    if (isActive(f, t)) body(f.body).wake();
  }
  if (withGravity) {
    refreshAwake();  // the forces above may have woken bodies
    for (const std::uint32_t i : awakeList_) {
      RigidBody& body = table_->bodies[i];
      if (body.isDynamic()) body.applyForce(body.mass() * settings_.gravity);
    }
  }
  for (const ScriptedForce& f : forces_) {
    if (!isActive(f, t)) continue;
    RigidBody& body = this->body(f.body);
    if (f.forceFrame == Frame::Body && f.pointFrame == Frame::Body) {
      // Fixed in the body: its torque r x f turns with the body within a step (integrator.h).
      body.applyForce(body.rotation() * f.force);
      body.applyBodyTorque(f.point.cross(f.force));
      continue;
    }
    const auto [point, force] = inWorldFrame(f, body);
    body.applyForceAtPoint(force, point);
  }
  for (const Spring& spring : springs_) {
    RigidBody& body = this->body(spring.body);
    if (!body.awake()) continue;
    const auto [point, force] = forceOfSpring(spring, body);
    body.applyForceAtPoint(force, point);
  }
}

void World::integrateBodies(bool withGravity) {
  const double dt = settings_.timeStep;
  const Vec3 gravity = settings_.gravity;
  const bool addGravity = withGravity && gravity != Vec3::Zero();
  const std::vector<char>& advanced = solver_->advancedFlags();  // bodies the solver moved
  const std::size_t count = awakeList_.size();  // the awake bodies alone (refreshAwake)
  std::array<BodyState, kIntegrateBatch> next;
  std::array<RigidBody*, kIntegrateBatch> stepped;
  // euler-matrix without drift correction keeps each dynamic body's raw R (RigidBody::setState).
  const bool rawMatrix = settings_.integrator == Integrator::EulerMatrix && !settings_.driftCorrection;
  std::array<Mat3, kIntegrateBatch> raw;
  for (std::size_t first = 0; first < count; first += kIntegrateBatch) {
    const std::size_t end = std::min(count, first + kIntegrateBatch);
    std::size_t n = 0;  // awake bodies of the batch
    const auto commit = [&](std::size_t stepCount) {
      for (std::size_t k = 0; k < stepCount; ++k) {
        if (rawMatrix && stepped[k]->isDynamic()) {
          stepped[k]->setState(next[k], raw[k]);
        } else {
          stepped[k]->setState(next[k]);
        }
        stepped[k]->clearAccumulators();
      }
    };
    for (std::size_t k = first; k < end; ++k) {
      if (k + kPrefetchAhead < count) StepPrefetch::fetch(table_->bodies[awakeList_[k + kPrefetchAhead]]);
      const std::size_t i = awakeList_[k];
      RigidBody& body = table_->bodies[i];
      if (!body.awake() || (i < advanced.size() && advanced[i] != 0)) continue;
      if (body.isKinematic()) {
        next[n] = integrateKinematic(body.state(), body.stepInputs(), dt);
      } else {
        if (addGravity) body.applyForce(body.mass() * gravity);  // F = 0 + m g, as AccumulateForces would
        FreeFlowMemo* memo = usesFreeFlow(settings_.integrator) ? &body.freeFlowMemo() : nullptr;
        next[n] = integrate(settings_.integrator, body.state(), body.stepInputs(), dt, memo);
        if (rawMatrix) raw[n] = eulerMatrixUpdate(body.rotation(), body.angularVelocity(), dt);
      }
      if (!isFinite(next[n])) {
        commit(n);  // the bodies before it have stepped, as they would have one at a time
        reportDivergence(body, next[n]);
      }
      stepped[n++] = &body;
    }
    commit(n);
  }
}

std::uint64_t World::stateHash() const {
  std::uint64_t hash = kFnvOffsetBasis;
  auto mix = [&hash](double value) { hash = fnvMix(hash, value); };
  for (const RigidBody& body : table_->bodies) {
    const BodyState& s = body.state();
    for (int i = 0; i < 3; ++i) mix(s.position[i]);
    for (int i = 0; i < 4; ++i) mix(s.orientation.coeffs()[i]);
    for (int i = 0; i < 3; ++i) mix(s.linearMomentum[i]);
    for (int i = 0; i < 3; ++i) mix(s.angularMomentum[i]);
  }
  for (const std::unique_ptr<StepListener>& listener : listeners_) hash = listener->hashState(hash);
  return hash;
}

}  // namespace rbsim
