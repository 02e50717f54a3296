#include "py_world.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include <pybind11/stl.h>

#include "rbsim/integrate/free_rigid_body.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene_parts.h"
#include "rbsim/world/joint_changes.h"
#include "rbsim/world/made_names.h"
#include "to_json.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// Keyword arguments are named after the call they came with, in the place of a scene file.
constexpr const char* kWorldCall = "World()";
constexpr const char* kBodyCall = "World.add_body()";
constexpr const char* kPlaneCall = "World.add_plane()";
constexpr const char* kSpawnerCall = "World.add_spawner()";
constexpr const char* kForceCall = "World.add_force()";
constexpr const char* kJointCall = "World.add_joint()";
constexpr const char* kPoseCall = "World.set_pose()";
// Ctrl-C is looked for every this many steps: often enough to stop within a blink at 1000 bodies
// (about 40 ms), rarely enough that the check costs nothing for one body.
constexpr long long kStepsBetweenSignalChecks = 256;

// `count` finite numbers from a sequence or array, or InputError naming the keyword.
Eigen::VectorXd finiteNumbers(const py::object& value, std::size_t count, const char* field, const char* call = kPoseCall) {
  const nlohmann::json j = toJson(value, call, field);
  const std::string expected = "expected " + std::to_string(count) + " finite numbers";
  if (!j.is_array() || j.size() != count) throw InputError(call, field, expected);
  Eigen::VectorXd out(static_cast<Eigen::Index>(count));
  for (std::size_t i = 0; i < count; ++i) {
    if (!j[i].is_number() || !std::isfinite(j[i].get<double>())) throw InputError(call, field, expected);
    out[static_cast<Eigen::Index>(i)] = j[i].get<double>();
  }
  return out;
}

// Worlds made so far: each World's ids carry its number (the GIL serialises construction).
std::uint64_t worldsMade = 0;

}  // namespace

PyWorld PyWorld::fromKeywords(const py::kwargs& world) {
  Scene scene;
  scene.file = kWorldCall;
  scene.title = "rbsim (Python)";
  parseWorldBlock(JsonObject(toJson(world, kWorldCall, ""), kWorldCall, "", kWorldKeys), scene);
  return PyWorld(std::move(scene));
}

PyWorld::PyWorld(Scene scene) : scene_(std::move(scene)), world_(buildWorld(scene_)), serial_(++worldsMade) {
  for (const RigidBody& body : world_.bodies()) names_.insert(body.name());
  if (scene_.file != kWorldCall) blocks_.loadedFrom(scene_.file);
}

void PyWorld::waitIdle() const {
  while (busy_->stepping) {
    py::gil_scoped_release release;  // the stepping thread takes the GIL back when it ends
    std::unique_lock<std::mutex> lock(busy_->mutex);
    busy_->idle.wait(lock, [this] { return !busy_->stepping; });
  }
}

std::size_t PyWorld::index(const PyBodyId& id, const char* call) const {
  waitIdle();
  if (id.world != serial_) {
    throw InputError(call, "body", "this id is of another World (World " + std::to_string(id.world) + "; this is World " +
                                       std::to_string(serial_) + "); ids name bodies of the World that gave them");
  }
  if (!world_.isValid(id.id)) {
    throw InputError(call, "body", "no body has this id (slot " + std::to_string(id.id.slot) + ", generation " +
                                       std::to_string(id.id.generation) + "): it was removed");
  }
  return world_.indexOf(id.id);
}

PyBodyId PyWorld::addBody(const py::kwargs& body) {
  nlohmann::json keys = toJson(body, kBodyCall, "");
  // After the conversion, which may run Python code (and so let another thread start a step), and
  // before the first look at the World; so in every call below.
  waitIdle();
  const std::size_t index = world_.bodies().size();
  if (keys.is_object() && !keys.contains("name")) {
    std::size_t n = index;
    while (names_.count("body" + std::to_string(n)) != 0) ++n;
    keys["name"] = "body" + std::to_string(n);
  }
  const BodyBlock block = parseBodyBlock(keys, kBodyCall, "", "", world_.settings(), index);
  if (names_.count(block.def.name) != 0) {
    throw InputError(kBodyCall, "name", "duplicate body name \"" + block.def.name + "\"");
  }
  // Nor one a spawner will give (issue 56, item 4).
  for (const Spawner& spawner : rbsim::spawners(world_)) {
    if (spawnerMakesName(spawner.def, block.def.name)) throw InputError(kBodyCall, "name", madeNameProblem(spawner.def, block.def.name));
  }
  const BodyId id = world_.addBody(block.def);
  names_.insert(block.def.name);
  blocks_.addBody(id, keys, world_.body(id));
  scene_.inertiaMethods.push_back(block.inertiaMethod);
  // Filed by name, as a scene file's are (Scene::colors); a name used before loses its old colour.
  if (block.color) {
    scene_.colors.byBody[block.def.name] = *block.color;
  } else {
    scene_.colors.byBody.erase(block.def.name);
  }
  // The block names its body as a scene's body `index` would be named; in this World, where
  // bodies may have been removed, the body has the id addBody gave it.
  for (ScriptedForce f : block.forces) {
    f.body = id;
    world_.addForce(f);
  }
  for (PoseEvent e : block.poseEvents) {
    e.body = id;
    world_.addPoseEvent(e);
  }
  for (Spring s : block.springs) {
    s.body = id;
    rbsim::addSpring(world_, s);
  }
  for (KinematicMotion m : block.motions) {
    m.body = id;
    rbsim::setKinematicMotion(world_, m);
  }
  return wrap(id);
}

void PyWorld::removeBody(const PyBodyId& id) {
  const std::size_t i = index(id, "World.remove_body()");
  names_.erase(world_.bodies()[i].name());
  world_.destroyBody(id.id);
  // The World moved its last body into the hole (world.h); the names of inertia methods follow.
  scene_.inertiaMethods[i] = scene_.inertiaMethods.back();
  scene_.inertiaMethods.pop_back();
}

std::size_t PyWorld::addSpawner(const py::kwargs& spawn) {
  nlohmann::json keys = toJson(spawn, kSpawnerCall, "");
  waitIdle();
  const auto spawnerNamed = [this](const std::string& name) {
    return std::any_of(rbsim::spawners(world_).begin(), rbsim::spawners(world_).end(), [&](const Spawner& s) { return s.def.name == name; });
  };
  if (keys.is_object() && !keys.contains("name")) keys["name"] = freeSpawnerName(spawnerNamed);
  std::optional<Vec3> color;
  const SpawnerDef def = parseSpawnerBlock(keys, kSpawnerCall, "", "", world_.settings(), &color);
  // Its bodies' names must be its own (issue 56, item 4).
  if (spawnerNamed(def.name)) {
    throw InputError(kSpawnerCall, "name", "another spawner is named \"" + def.name + "\"; expected a name of its own");
  }
  for (const std::string& name : names_) {
    if (spawnerMakesName(def, name)) {
      throw InputError(kSpawnerCall, "name", "its bodies are named " + def.name + "_k" + (def.ragdoll ? "_bone" : "") +
                                                 " (k = 0, 1, ...), and a body is already named \"" + name +
                                                 "\"; expected a name of its own");
    }
  }
  try {
    rbsim::addSpawner(world_, def);
  } catch (const std::invalid_argument& e) {
    throw InputError(kSpawnerCall, "", e.what());  // the engine's checks (addSpawner, world/spawner.h)
  }
  if (color) scene_.colors.bySpawner[def.name] = *color;
  blocks_.addSpawner(std::move(keys));
  return rbsim::spawners(world_).size() - 1;
}

void PyWorld::setKillVolume(const py::object& volume) {
  constexpr const char* kCall = "World.kill_volume";
  Aabb box;
  if (!volume.is_none()) {
    const Eigen::VectorXd corners = finiteNumbers(volume, 6, "kill_volume", kCall);
    box.min = Vec3(corners[0], corners[1], corners[2]);
    box.max = Vec3(corners[3], corners[4], corners[5]);
    if (!(box.min.array() < box.max.array()).all()) {
      throw InputError(kCall, "kill_volume", "expected (min x, min y, min z, max x, max y, max z) with min < max along every axis");
    }
  }
  waitIdle();
  rbsim::setKillVolume(world_, box);
}

py::object PyWorld::killVolume() const {
  waitIdle();
  const Aabb& box = rbsim::killVolume(world_);
  if (box.empty()) return py::none();
  return py::make_tuple(box.min.x(), box.min.y(), box.min.z(), box.max.x(), box.max.y(), box.max.z());
}

std::size_t PyWorld::addPlane(const py::kwargs& plane) {
  nlohmann::json keys = toJson(plane, kPlaneCall, "");
  const auto [p, material] = parsePlaneBlock(keys, kPlaneCall, "");
  waitIdle();
  world_.addPlane(p, material);
  blocks_.addPlane(std::move(keys));
  return world_.planes().size() - 1;
}

void PyWorld::addForce(const PyBodyId& id, const py::kwargs& force) {
  const nlohmann::json keys = toJson(force, kForceCall, "");
  const std::size_t i = index(id, kForceCall);
  const RigidBody& body = world_.bodies()[i];
  if (!body.isDynamic()) {
    throw InputError(kForceCall, "body", "\"" + body.name() + "\" is " + (body.isStatic() ? "static" : "kinematic") +
                                             ": forces act on dynamic bodies only");
  }
  ScriptedForce f = parseForceBlock(keys, kForceCall, "", i, body.fileFrame().axes);
  f.body = id.id;
  world_.addForce(f);
  blocks_.addForce(id.id, keys);
}

std::size_t PyWorld::addJoint(const py::kwargs& joint) {
  const nlohmann::json keys = toJson(joint, kJointCall, "");
  waitIdle();
  const JointDef def = parseJointBlock(keys, kJointCall, "", world_);
  std::size_t row = 0;
  try {
    row = indexOf(world_, world_.addJoint(def));
  } catch (const std::invalid_argument& e) {
    throw InputError(kJointCall, "", e.what());
  }
  blocks_.addJoint(keys, world_.joints()[row]);
  return row;
}

void PyWorld::setPose(const PyBodyId& id, const py::object& position, const py::object& orientation,
                      const py::object& velocity, const py::object& angularVelocity) {
  // Every value is checked before any is set, so a refused call changes nothing.
  std::optional<Vec3> x, v, w;
  std::optional<Quat> q;
  if (!position.is_none()) x = Vec3(finiteNumbers(position, 3, "position"));
  if (!orientation.is_none()) {
    const Eigen::VectorXd c = finiteNumbers(orientation, 4, "orientation");
    q = Quat(c[0], c[1], c[2], c[3]);
    if (std::abs(q->norm() - 1.0) > kRotationTolerance) {
      throw InputError(kPoseCall, "orientation", "expected a unit quaternion (w, x, y, z); its norm is " +
                                                     formatNumber(q->norm()));
    }
  }
  if (!velocity.is_none()) v = Vec3(finiteNumbers(velocity, 3, "velocity"));
  if (!angularVelocity.is_none()) w = Vec3(finiteNumbers(angularVelocity, 3, "angular_velocity"));
  index(id, kPoseCall);  // a stale id is an input error, not an invalid_argument; waits for a step
  RigidBody& body = world_.body(id.id);
  if (!body.isDynamic() && !body.isKinematic() && (v || w)) {
    throw InputError(kPoseCall, "velocity", "a static body cannot move");
  }
  // A scene's ranges, so that a pose set from Python is one a scene could give.
  checkPoseRanges(kPoseCall, x ? &*x : nullptr, v ? &*v : nullptr, w ? &*w : nullptr,
                  0.5 * (body.mesh().boundsMax() - body.mesh().boundsMin()).norm());
  if (x) body.setPosition(*x);
  if (q) body.setOrientation(*q);
  if (v) body.setVelocity(*v);
  if (w) body.setAngularVelocity(*w);
}

void PyWorld::step(long long steps) {
  if (steps < 0) throw InputError("World.step()", "steps", "expected a number of steps >= 0, got " + std::to_string(steps));
  waitIdle();  // a second thread's step() waits for the first's
  // Marked busy for the whole call, the signal checks between chunks included; cleared however it
  // ends, with the GIL held (the destructor runs after the release below has ended).
  busy_->stepping = true;
  struct Idle {
    Busy& busy;
    ~Idle() {
      {
        const std::lock_guard<std::mutex> lock(busy.mutex);
        busy.stepping = false;
      }
      busy.idle.notify_all();
    }
  } idle{*busy_};
  std::exception_ptr failed;
  stepEvents_.clear();  // the events of this call's steps, gathered after each
  for (long long done = 0; done < steps;) {
    const long long chunk = std::min(kStepsBetweenSignalChecks, steps - done);
    {
      // Other Python threads run while this World steps (as MuJoCo's mj_step lets them); a call
      // of theirs on this World waits (waitIdle).
      py::gil_scoped_release release;
      try {
        for (long long i = 0; i < chunk; ++i) {
          world_.step();
          gatherContactEvents(world_, stepEvents_);
        }
      } catch (...) {
        failed = std::current_exception();  // a failed step is undone (World::step); raised below
      }
    }
    done += chunk;
    // Spawners and the kill volume add and remove bodies as the World steps, the steps before a
    // failed one included: the names follow.
    if (!rbsim::spawners(world_).empty() || !rbsim::killVolume(world_).empty()) {
      names_.clear();
      for (const RigidBody& body : world_.bodies()) names_.insert(body.name());
    }
    if (failed) std::rethrow_exception(failed);
    // Ctrl-C in a notebook stops a long run between two steps (the World stays consistent).
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
}

void PyWorld::runOnWorld(const std::function<void(World&)>& work) {
  waitIdle();
  struct Names {
    PyWorld& w;
    ~Names() {
      w.names_.clear();
      for (const RigidBody& body : w.world_.bodies()) w.names_.insert(body.name());
    }
  } names{*this};
  work(world_);
}

py::array_t<double> PyWorld::exactRotation(const PyBodyId& id, const py::array_t<double, py::array::c_style | py::array::forcecast>& times) const {
  const RigidBody& body = world_.bodies()[index(id, "World.exact_rotation()")];
  // The flow moves the principal frame (free_flight_error.cpp does the same for the overlay).
  const Quat principalToBody(body.principalAxes());
  const FreeRigidBodyFlow flow(body.orientation() * principalToBody, body.state().angularMomentum, body.principalMoments());
  const double* t = times.data();
  py::array_t<double> out({times.size(), py::ssize_t{4}});
  double* row = out.mutable_data();
  for (py::ssize_t i = 0; i < times.size(); ++i, row += 4) {
    if (!std::isfinite(t[i])) throw InputError("World.exact_rotation()", "times", "expected finite times [s]");
    const Quat q = flow.principalToWorld(t[i]) * principalToBody.conjugate();
    row[0] = q.w();
    row[1] = q.x();
    row[2] = q.y();
    row[3] = q.z();
  }
  return out;
}

}  // namespace rbsim::python
