// World.get_state and World.set_state (PyBullet's saveState and restoreState, MuJoCo's
// mj_getState and mj_setState), and the settings a running World takes as properties (PyBullet's
// setGravity, setTimeStep). A state is the whole World copied (World's copy constructor: bodies,
// contacts, warm starts, sleep timers, particles, soft bodies), so going on from a restored state
// is bit for bit the uninterrupted run (tests/python/test_state.py).
#include <pybind11/pybind11.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "py_world.h"
#include "rbsim/integrate/integrator.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene_parts.h"
#include "run/phase.h"
#include "state_file.h"
#include "to_json.h"
#include "arguments.h"
#include "rbsim/world/world_snapshot.h"

namespace py = pybind11;

namespace rbsim::python {

void PyWorld::setSetting(const char* key, const py::handle& value) {
  const std::string call = "World";  // the message reads "World: dt: expected ..."
  nlohmann::json block = nlohmann::json::object();
  block[key] = toJson(value, call, key);
  waitIdle();  // after the conversion, which may run Python code (PyWorld::waitIdle)
  Settings settings = world_.settings();
  parseWorldSettings(JsonObject(block, call, "", {key}), settings);
  try {
    world_.setSettings(settings);  // the broad phase and PGS-with-joints checks
  } catch (const std::invalid_argument& e) {
    throw InputError(call, key, e.what());
  }
  scene_.settings = settings;
}

std::shared_ptr<PyWorld::Saved> PyWorld::save() const {
  waitIdle();
  auto saved = std::make_shared<Saved>(Saved{scene_, world_, {}, {}, names_, serial_});
  saved->time = world_.time();
  saved->stepCount = world_.stepCount();
  saved->bodyCount = world_.bodies().size();
  return saved;
}

void PyWorld::restore(const Saved& saved) {
  constexpr const char* kCall = "World.set_state()";
  waitIdle();
  if (!saved.world) {
    // Read from bytes: any World built as the state's was supplies the bodies' shapes.
    World world = [&] {
      try {
        return loadWorldSnapshot(saved.snapshot, world_, saved.source);
      } catch (const std::invalid_argument& e) {
        throw InputError(kCall, "state", std::string(e.what()) + " (a state goes into a World built as its own was: " +
                                             "the same scene, the same bodies added)");
      }
    }();
    world_ = std::move(world);
    names_.clear();
    for (const RigidBody& body : world_.bodies()) names_.insert(body.name());
    scene_.settings = world_.settings();
    scene_.inertiaMethods = saved.inertiaMethods;
    return;
  }
  if (saved.serial != serial_) {
    throw InputError(kCall, "state",
                     "this state is of another World (World " + std::to_string(saved.serial) + "; this is World " +
                         std::to_string(serial_) + "); a state goes back into the World it was taken from (a pickled "
                         "or saved state goes into any World built as its own was)");
  }
  World world(*saved.world);  // copied before anything changes: the state stays for another restore
  world_ = std::move(world);
  scene_ = saved.scene;
  names_ = saved.names;
}

PyWorld PyWorld::fromState(const Saved& saved) {
  constexpr const char* kCall = "World.from_state()";
  if (saved.world) {
    PyWorld w(saved.scene);
    w.world_ = *saved.world;
    w.names_ = saved.names;
    return w;
  }
  if (saved.scene.file == "World()" || saved.scene.file.empty()) {
    throw InputError(kCall, "state", "its World was built in Python (rbsim.World()), not from a scene file; build the "
                                     "same World and call World.set_state(state)");
  }
  // As rbsim.load_scene reads it; a scene of several compared worlds gives its first.
  PyWorld w(std::move(app::loadPhase(saved.scene.file, {}).worlds.front().scene));
  w.restore(saved);
  return w;
}

namespace {

using SavedState = std::shared_ptr<PyWorld::Saved>;

// A property over one key of the "world" block: read from the World's settings, written through
// PyWorld::setSetting.
template <typename Get>
void liveSetting(py::class_<PyWorld>& world, const char* key, Get get, const char* doc) {
  world.def_property(
      key, [get](const PyWorld& w) { return get(w.world().settings()); },
      [key](PyWorld& w, const py::object& value) { w.setSetting(key, value); }, doc);
}

}  // namespace

void bindWorldState(py::module_& m, py::class_<PyWorld>& world) {
  py::class_<PyWorld::Saved, SavedState>(m, "State",
                                         "A World's whole state (World.get_state), for World.set_state: bodies, "
                                         "contacts, the solver's warm starts, sleep, particles and soft bodies. It "
                                         "pickles (and State.save writes it) as a World snapshot with the scene file: "
                                         "a worker process gives it to a World built as its own was")
      .def_property_readonly("time", [](const PyWorld::Saved& s) { return s.time; }, "[s] when it was taken")
      .def_property_readonly("step_count", [](const PyWorld::Saved& s) { return s.stepCount; })
      .def_readonly("world", &PyWorld::Saved::serial, "the number of the World it was taken from")
      .def_property_readonly("scene", [](const PyWorld::Saved& s) { return s.scene.file; },
                             "the scene file its World was built from (\"World()\": built in Python)")
      .def("__repr__",
           [](const PyWorld::Saved& s) {
             return "State(world=" + std::to_string(s.serial) + ", step_count=" + std::to_string(s.stepCount) +
                    ", bodies=" + std::to_string(s.bodyCount) + ")";
           })
      .def(py::pickle([](const PyWorld::Saved& s) { return py::bytes(stateBytes(s, "State.__getstate__()")); },
                      [](const py::bytes& bytes) { return stateFromBytes(std::string(bytes), "State.__setstate__()"); }))
      .def("save",
           [](const PyWorld::Saved& s, const py::object& path) {
             saveStateFile(s, pathArgument(path, "State.save()", "path"));
           },
           py::arg("path"),
           "save(self, /, path)\n--\n\nwrites the state (the bytes pickle gives) to path, whole or not at all; "
           "rbsim.load_state(path) reads it back");

  m.def("load_state", [](const py::object& path) { return loadStateFile(pathArgument(path, "rbsim.load_state()", "path")); },
        py::arg("path"),
        "load_state(path)\n--\n\n-> State: a state State.save wrote, for World.set_state of a World built as its own "
        "was, or World.from_state");

  world
      .def_static("from_state", [](const SavedState& state) { return PyWorld::fromState(*state); }, py::arg("state"),
                  "from_state(state)\n--\n\n-> World: a new World built from the state's scene file and set to the "
                  "state (a pickled or saved state: the scene file as read, without overrides)")
      .def("get_state", [](const PyWorld& w) { return w.save(); },
           "get_state(self, /)\n--\n\n-> State: everything the World will step from, copied; set_state(state) goes back to it")
      .def("set_state",
           [](PyWorld& w, const py::object& state) {
             if (!py::isinstance<PyWorld::Saved>(state)) {
               throw py::type_error("World.set_state(): state: expected an rbsim.State (World.get_state()), got " +
                                    std::string(py::str(py::type::of(state).attr("__name__"))));
             }
             w.restore(state.cast<const PyWorld::Saved&>());
           },
           py::arg("state"),
           "set_state(self, /, state)\n--\n\nback to a state this World gave, settings included; stepping on from it "
           "gives bit for bit what the World gave after it was taken. Ids of bodies added since are no longer valid.");

  liveSetting(world, "gravity", [](const Settings& s) { return py::make_tuple(s.gravity.x(), s.gravity.y(), s.gravity.z()); },
              "(gx, gy, gz) [m/s^2]; settable, from the next step");
  liveSetting(world, "dt", [](const Settings& s) { return s.timeStep; },
              "[s]; settable: World.time goes on from where it is, the new step counts from now");
  liveSetting(world, "integrator", [](const Settings& s) { return std::string(integratorName(s.integrator)); },
              "settable: one of rbsim.integrators(), from the next step");
  liveSetting(world, "solver", [](const Settings& s) { return std::string(contactSolverName(s.solver)); },
              "\"soft-step\", \"pgs\" or \"lcp\"; settable (the new solver starts without warm starts; PGS and LCP refuse joints)");
  liveSetting(world, "substeps", [](const Settings& s) { return s.substeps; }, "soft-step substeps per step; settable");
  liveSetting(world, "friction", [](const Settings& s) { return std::string(frictionModelName(s.friction)); },
              "\"cone\" or \"seed000\"; settable");
  liveSetting(world, "restitution_threshold", [](const Settings& s) { return s.restitutionThreshold; },
              "[m/s] below this approach speed contacts do not bounce; settable");
}

}  // namespace rbsim::python
