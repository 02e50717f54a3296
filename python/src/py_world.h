#pragma once
// rbsim.World: a World with the Scene it came from (the view, the looks and the per-body inertia
// names a renderer reads), built from a scene file or from keyword arguments that are blocks of
// the scene format (engine/include/rbsim/scene/scene_parts.h), so Python meets the same keys and messages as
// the command line.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "scene_blocks.h"

namespace rbsim::python {

// A body's id as Python holds it: the World's BodyId and which World gave it, so that an id of
// one World is refused by another instead of naming a body of its own (issue 37).
struct PyBodyId {
  BodyId id;
  std::uint64_t world = 0;  // PyWorld::serial() of the World that gave it
};

// The contact events of every step of the last World.step(n) call, each with the World's step
// count before it (event_arrays.cpp): contactEvents(world) holds one step's.
struct StepEvents {
  ContactEvents events;
  std::vector<std::uint64_t> beginStep, endStep, hitStep;
  void clear() {
    events.clear();
    beginStep.clear();
    endStep.clear();
    hitStep.clear();
  }
};
// Appends the World's last step's events (after a successful World::step).
void gatherContactEvents(const World& world, StepEvents& out);

class PyWorld {
 public:
  // World(**world_block): the keys of a scene's "world" block (dt, integrator, gravity, ...).
  static PyWorld fromKeywords(const pybind11::kwargs& world);
  explicit PyWorld(Scene scene);

  // The keys of one entry of "bodies"; without "name", the first of body<N>, N = the body count
  // and up, that no body has (a removed body's default name may be taken again, a living one's not).
  PyBodyId addBody(const pybind11::kwargs& body);
  void removeBody(const PyBodyId& id);
  std::size_t addPlane(const pybind11::kwargs& plane);  // the keys of one entry of "planes"
  // The keys of one entry of "spawn", with a "period": bodies added while the World steps.
  std::size_t addSpawner(const pybind11::kwargs& spawn);
  // (min x, min y, min z, max x, max y, max z) [m] or None: bodies whose centre leaves it are removed.
  void setKillVolume(const pybind11::object& volume);
  pybind11::object killVolume() const;
  void addForce(const PyBodyId& id, const pybind11::kwargs& force);  // the keys of one entry of "forces"
  std::size_t addJoint(const pybind11::kwargs& joint);      // the keys of one entry of "joints"
  // Sets any of x, q (w, x, y, z: the state's own, as World.q reads), v and omega now, as seed
  // 004's manual change does: derived quantities follow and the body wakes. The values meet a
  // scene's ranges: coordinates within 1e6 m, speeds and the surface's speed of turning below c.
  void setPose(const PyBodyId& id, const pybind11::object& position, const pybind11::object& orientation,
               const pybind11::object& velocity, const pybind11::object& angularVelocity);
  void step(long long steps);  // steps >= 0; releases the GIL while stepping
  // Runs `work` on the World (World.run: the program's runner steps it), with the GIL held, then
  // brings the body names up to date as step() does, however `work` ends.
  void runOnWorld(const std::function<void(World&)>& work);
  // Runs `work` (which reads the World) with the GIL released, other threads' calls on this World
  // waiting meanwhile as they wait for a step (query_bindings.cpp).
  void whileBusy(const std::function<void()>& work);
  // The body's orientation (w, x, y, z) t [s] from now for each t of `times`, by the closed-form
  // torque-free motion (integrate/free_rigid_body.h) from its state now: the reference the
  // integrators' errors are measured against.
  pybind11::array_t<double> exactRotation(const PyBodyId& id, const pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>& times) const;

  // World.<key> = value for a key of a scene's "world" block that a running World takes
  // (World::setSettings): read and checked as in a scene file, InputError naming the key.
  void setSetting(const char* key, const pybind11::handle& value);

  // A saved state (World.get_state): the whole World copied, with the Scene and names beside it;
  // or, read from bytes (a pickle, rbsim.load_state), the World's snapshot (world/world_snapshot.h)
  // with the scene file and the bodies' inertia methods (python/src/state_file.cpp).
  struct Saved {
    Scene scene;
    std::optional<World> world;            // taken here; empty for a state read from bytes
    std::vector<std::uint8_t> snapshot;    // read from bytes: the World's snapshot
    std::vector<std::string> inertiaMethods;  // read from bytes: per body, in World order
    std::unordered_set<std::string> names;
    std::uint64_t serial;  // the World it was taken from (in the process that took it)
    double time = 0.0;            // [s]
    std::uint64_t stepCount = 0;
    std::size_t bodyCount = 0;
    std::string source = "State";  // read from bytes: the file (or the pickle) it came from, for messages
  };
  std::shared_ptr<Saved> save() const;
  // Back to `saved`, bit for bit (World.set_state); InputError for a state of another World. A
  // state read from bytes goes into any World built as its World was (the same scene, the same
  // bodies added): the snapshot takes the bodies' shapes from it.
  void restore(const Saved& saved);
  // World.from_state: a World built from the state's scene file, then restored.
  static PyWorld fromState(const Saved& saved);

  // Every reader and writer of the World goes through these, or calls waitIdle() first.
  World& world() {
    waitIdle();
    return world_;
  }
  const World& world() const {
    waitIdle();
    return world_;
  }
  const Scene& scene() const {
    waitIdle();
    return scene_;
  }
  Scene& scene() {  // a change that the Scene records (World.set_body's inertia method)
    waitIdle();
    return scene_;
  }
  // One World, one thread at a time (issue 56, item 6): step() releases the GIL, so another Python
  // thread may call this World mid-step. It waits here, the GIL released, until the step ends.
  // Called with the GIL held; returns with it held and no step running.
  void waitIdle() const;
  // The body's row now; InputError naming `call` and the field "body" for an id of another World
  // or of a removed body.
  std::size_t index(const PyBodyId& id, const char* call) const;
  PyBodyId wrap(BodyId id) const { return {id, serial_}; }
  std::uint64_t serial() const { return serial_; }
  const SceneBlocks& blocks() const { return blocks_; }  // what World.save_scene writes
  const StepEvents& stepEvents() const {
    waitIdle();
    return stepEvents_;
  }

 private:
  Scene scene_;  // settings, view, looks; inertiaMethods kept per body in the World's order
  World world_;
  std::unordered_set<std::string> names_;  // every body's, for add_body's duplicate check
  std::uint64_t serial_;                   // this World's number among those the module made
  SceneBlocks blocks_;                     // the blocks it was given, for World.save_scene
  StepEvents stepEvents_;                  // of the last step() call's steps
  // Whether a step() runs, written with the GIL and the mutex held; a unique_ptr keeps PyWorld movable.
  struct Busy {
    std::mutex mutex;
    std::condition_variable idle;
    std::atomic<bool> stepping{false};
  };
  std::unique_ptr<Busy> busy_ = std::make_unique<Busy>();
};

// Every body's state as NumPy arrays, one row per body in World order (python/src/state_arrays.cpp).
void bindStateArrays(pybind11::class_<PyWorld>& world);
void bindContacts(pybind11::class_<PyWorld>& world);  // contact_arrays.cpp
void bindJoints(pybind11::class_<PyWorld>& world);     // joint_arrays.cpp
void bindParticles(pybind11::class_<PyWorld>& world);  // particle_arrays.cpp
void bindContactEvents(pybind11::class_<PyWorld>& world);  // event_arrays.cpp
// World.ray_cast, ray_cast_batch, shape_cast, overlap, closest_point, query_aabb (query_bindings.cpp).
void bindQueries(pybind11::class_<PyWorld>& world);
// World.get_state and set_state, and the settings a running World takes as properties
// (world_state.cpp).
void bindWorldState(pybind11::module_& m, pybind11::class_<PyWorld>& world);
// World.save_scene, World.run's outputs (trace, recording, glTF), rbsim.run and
// rbsim.read_recording (disk_bindings.cpp).
void bindDisk(pybind11::module_& m, pybind11::class_<PyWorld>& world);
// World.run and rbsim.run (run_bindings.cpp; absent from the physics-only module: render_off.cpp).
void bindRun(pybind11::module_& m, pybind11::class_<PyWorld>& world);
// World.set_body, body_properties, set_joint and remove_joint: changes while running (change_bindings.cpp).
void bindChanges(pybind11::class_<PyWorld>& world);

}  // namespace rbsim::python
