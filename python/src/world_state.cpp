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
#include "to_json.h"

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
  return std::make_shared<Saved>(Saved{scene_, world_, names_, serial_});
}

void PyWorld::restore(const Saved& saved) {
  waitIdle();
  if (saved.serial != serial_) {
    throw InputError("World.set_state()", "state",
                     "this state is of another World (World " + std::to_string(saved.serial) + "; this is World " +
                         std::to_string(serial_) + "); a state goes back into the World it was taken from");
  }
  World world(saved.world);  // copied before anything changes: the state stays for another restore
  world_ = std::move(world);
  scene_ = saved.scene;
  names_ = saved.names;
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
                                         "contacts, the solver's warm starts, sleep, particles and soft bodies")
      .def_property_readonly("time", [](const PyWorld::Saved& s) { return s.world.time(); }, "[s] when it was taken")
      .def_property_readonly("step_count", [](const PyWorld::Saved& s) { return s.world.stepCount(); })
      .def_readonly("world", &PyWorld::Saved::serial, "the number of the World it was taken from")
      .def("__repr__", [](const PyWorld::Saved& s) {
        return "State(world=" + std::to_string(s.serial) + ", step_count=" + std::to_string(s.world.stepCount()) +
               ", bodies=" + std::to_string(s.world.bodies().size()) + ")";
      });

  world
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
