// The Python module `rbsim` (issue 23): pybind11 over the engine's public API and the scene
// format. Errors become Python exceptions carrying the command line's messages: InputError (a
// ValueError, with .file, .field and .problem), SimulationError and RenderError (RuntimeErrors).
// A call checks its arguments and names itself; an engine check it did not repeat
// (std::invalid_argument) is still an InputError, of the file "rbsim" (issue 56, item 8).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <utility>

#include "arguments.h"
#include "py_world.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/scene/scene_parts.h"
#include "render/data_dir.h"
#include "render/render_error.h"
#include "run/paths.h"
#include "run/scene_catalogue.h"
#include "run/phase.h"

namespace py = pybind11;

namespace rbsim::python {
void bindRendering(py::module_& m);  // py_render.cpp (render_off.cpp in a physics-only build)
}  // namespace rbsim::python

namespace {

using rbsim::BodyId;
using rbsim::python::bodyArgument;
using rbsim::python::givenKeywords;
using rbsim::python::intArgument;
using rbsim::python::pathArgument;
using rbsim::python::PyBodyId;
using rbsim::python::PyWorld;
using rbsim::python::requireKeywordsOnly;
using rbsim::python::stringListArgument;

// The exception types live as long as the module (they are its attributes); plain handles avoid
// destructors running after the interpreter has gone.
PyObject* inputErrorType = nullptr;
PyObject* simulationErrorType = nullptr;
PyObject* renderErrorType = nullptr;

void raiseInputError(const rbsim::InputError& e) {
  py::object exception = py::reinterpret_borrow<py::object>(inputErrorType)(e.what());
  exception.attr("file") = e.file();
  exception.attr("field") = e.field();
  exception.attr("problem") = e.problem();
  PyErr_SetObject(inputErrorType, exception.ptr());
}

void translate(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const rbsim::InputError& e) {
    raiseInputError(e);
  } catch (const std::invalid_argument& e) {
    raiseInputError(rbsim::InputError("rbsim", "", e.what()));
  } catch (const rbsim::SimulationError& e) {
    PyErr_SetString(simulationErrorType, e.what());
  } catch (const rbsim::render::RenderError& e) {
    PyErr_SetString(renderErrorType, e.what());
  }
}

std::string idRepr(const PyBodyId& id) {
  return "BodyId(slot=" + std::to_string(id.id.slot) + ", generation=" + std::to_string(id.id.generation) +
         ", world=" + std::to_string(id.world) + ")";
}

// Every key of a scene's "world" block with the value it has (rbsim::worldBlockJson), so World.settings
// names what World() takes and nothing else.
py::dict settingsDict(const rbsim::Scene& scene) {
  py::dict d = py::module_::import("json").attr("loads")(rbsim::worldBlockJson(scene).dump());
  for (const auto& [key, value] : d) {
    if (py::isinstance<py::list>(value)) d[key] = py::tuple(py::reinterpret_borrow<py::list>(value));  // gravity, as World.gravity reads
  }
  return d;
}

// World()'s signature, "__init__(self, /, *, gravity=(0.0, -9.81, 0.0), dt=..., ...)", from the
// defaults worldBlockJson writes for a default scene: the parser's own. "threads" (the machine's
// cores) and "steps" (the duration's) default to None, as every key does that is left out.
std::string worldInitDoc() {
  const nlohmann::json defaults = rbsim::worldBlockJson(rbsim::Scene{});
  const py::object loads = py::module_::import("json").attr("loads");
  std::string signature = "__init__(self, /, *";
  for (const char* key : rbsim::kWorldKeys) {
    std::string value = "None";
    if (defaults.contains(key) && std::string(key) != "threads") {
      py::object v = loads(defaults.at(key).dump());
      if (py::isinstance<py::list>(v)) v = py::tuple(v);
      value = py::repr(v);
    }
    signature += std::string(", ") + key + "=" + value;
  }
  return signature + ")\n--\n\nA World from the keys of a scene's \"world\" block (docs/scene-format.md), e.g. " +
         "World(dt=1/60, integrator=\"rk4\"); None: the default (threads: the machine's cores)";
}

// The compiled module is rbsim._rbsim, which the package rbsim re-exports (python/rbsim/__init__.py).
// pybind11 names each class's and function's __module__ after the module's __name__ when it is
// defined: while the module is filled it is named "rbsim", where its users find the names
// (rbsim.World.__module__, pickle, help()), and gets its own name back afterwards.
class PublicName {
 public:
  PublicName(py::module_ m, const char* name) : m_(std::move(m)), own_(m_.attr("__name__")) { m_.attr("__name__") = name; }
  ~PublicName() {
    if (PyObject_SetAttrString(m_.ptr(), "__name__", own_.ptr()) != 0) PyErr_Clear();  // a destructor must not throw
  }
  PublicName(const PublicName&) = delete;
  PublicName& operator=(const PublicName&) = delete;

 private:
  py::module_ m_;
  py::object own_;
};

}  // namespace

PYBIND11_MODULE(_rbsim, m) {
  const PublicName publicName(m, "rbsim");
  // Each call's docstring opens with its signature as Python reads it (types included):
  // pybind11's would show "object" for the parameters arguments.h converts by hand.
  py::options options;
  options.disable_function_signatures();
  m.doc() = "rbsim: rigid bodies for physically based animation coursework (see docs/python.md)";
  m.attr("__version__") = RBSIM_VERSION;
  // The state arrays are NumPy arrays: without NumPy the import fails here, saying so, and not
  // at the first w.x with "No module named 'numpy'".
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set&) {
    throw py::import_error("rbsim needs NumPy: apt-get install python3-numpy (Debian), or pip install numpy in a venv");
  }

  inputErrorType = PyErr_NewException("rbsim.InputError", PyExc_ValueError, nullptr);
  simulationErrorType = PyErr_NewException("rbsim.SimulationError", PyExc_RuntimeError, nullptr);
  renderErrorType = PyErr_NewException("rbsim.RenderError", PyExc_RuntimeError, nullptr);
  m.attr("InputError") = py::handle(inputErrorType);
  m.attr("SimulationError") = py::handle(simulationErrorType);
  m.attr("RenderError") = py::handle(renderErrorType);
  py::register_exception_translator(translate);

  m.def(
      "data_dirs",
      [] {
        py::dict d;
        d["assets"] = rbsim::app::assetDir();
        d["shaders"] = rbsim::render::defaultShaderDir();
        return d;
      },
      "data_dirs()\n--\n\n-> {\"assets\": path, \"shaders\": path}: the folders the module reads scenes by name and shaders "
      "from (<prefix>/share/rbsim when installed; `rbsim list` prints the program's)");
  m.def("integrators", &rbsim::integratorNames, "integrators()\n--\n\n-> [str]: the names world.integrator accepts");
  m.def("solvers", [] { return std::vector<std::string>{"soft-step", "pgs", "lcp"}; },
        "solvers()\n--\n\n-> [str]: the names world.solver accepts");

  py::class_<PyBodyId>(m, "BodyId",
                       "A body's handle: stays valid while the body exists (Box2D's b2BodyId), in the World that gave it")
      .def_property_readonly("slot", [](const PyBodyId& id) { return id.id.slot; })
      .def_property_readonly("generation", [](const PyBodyId& id) { return id.id.generation; })
      .def_readonly("world", &PyBodyId::world, "the number of the World that gave it")
      .def("__eq__", [](const PyBodyId& a, const py::object& b) {
        return py::isinstance<PyBodyId>(b) && a.id == b.cast<PyBodyId>().id && a.world == b.cast<PyBodyId>().world;
      })
      .def("__hash__", [](const PyBodyId& id) {
        return std::hash<std::uint64_t>{}((static_cast<std::uint64_t>(id.id.generation) << 32) | id.id.slot) ^ (id.world * 0x9e3779b97f4a7c15ULL);
      })
      .def("__repr__", &idRepr);

  py::class_<rbsim::Scene>(m, "Scene", "A scene file, parsed (rbsim.load_scene)")
      .def_readonly("file", &rbsim::Scene::file)
      .def_readonly("title", &rbsim::Scene::title)
      .def_readonly("duration", &rbsim::Scene::duration, "[s]")
      .def_property_readonly("steps", &rbsim::Scene::stepCount, "steps covering the duration")
      .def_property_readonly("settings", [](const rbsim::Scene& s) { return settingsDict(s); })
      .def("world", [](const rbsim::Scene& s) { return PyWorld(s); }, "world(self, /)\n--\n\n-> World: a new World holding the scene");

  // Through the program's phase loader (app/run/phase.h), so a scene file means what it means to
  // `rbsim run`, "compare" block and its messages included; a shipped scene may be named alone.
  m.def(
      "load_scene",
      [](const py::object& pathArg, const py::object& overridesArg) {
        const std::string given = pathArgument(pathArg, "rbsim.load_scene()", "path");
        const auto overrides = stringListArgument(overridesArg, "rbsim.load_scene()", "overrides");
        const std::string path = rbsim::app::resolveScene(given);  // after every argument is checked
        rbsim::app::Phase phase = rbsim::app::loadPhase(path, overrides);
        if (phase.compared()) {
          throw rbsim::InputError(path, "compare", "the scene compares " + phase.compareKey + " over " +
                                                       std::to_string(phase.worlds.size()) +
                                                       " worlds; rbsim.load_comparison gives one scene per value");
        }
        return std::move(phase.worlds.front().scene);
      },
      py::arg("path"), py::arg("overrides") = py::list(),
      "load_scene(path, overrides=())\n--\n\n-> Scene: a scene file (or a shipped scene's name, "
      "as in `rbsim list`) with --set overrides, e.g. overrides=[\"world.dt=0.01\"]");
  m.def(
      "load_comparison",
      [](const py::object& pathArg, const py::object& overridesArg) {
        const std::string given = pathArgument(pathArg, "rbsim.load_comparison()", "path");
        const auto overrides = stringListArgument(overridesArg, "rbsim.load_comparison()", "overrides");
        const std::string path = rbsim::app::resolveScene(given);  // after every argument is checked
        rbsim::app::Phase phase = rbsim::app::loadPhase(path, overrides);
        std::vector<std::pair<std::string, rbsim::Scene>> scenes;
        for (rbsim::app::PhaseWorld& w : phase.worlds) scenes.emplace_back(w.label, std::move(w.scene));
        return scenes;
      },
      py::arg("path"), py::arg("overrides") = py::list(),
      "load_comparison(path, overrides=())\n--\n\n-> [(label, Scene)]: one scene per value of the file's \"compare\" "
      "block (one, unlabelled, without it)");

  static const std::string worldInit = worldInitDoc();  // the docstring outlives the module's init
  py::class_<PyWorld> world(m, "World",
                            "World(**world): the keys of a scene's \"world\" block, e.g. World(dt=1/60, "
                            "integrator=\"rk4\", solver=\"pgs\")");
  world
      .def(py::init([](const py::args& args, const py::kwargs& kwargs) {
             requireKeywordsOnly(args, "World()", "a scene's \"world\" block");
             return PyWorld::fromKeywords(givenKeywords(kwargs));
           }),
           worldInit.c_str())
      .def("add_body",
           [](PyWorld& w, const py::args& args, const py::kwargs& body) {
             requireKeywordsOnly(args, "World.add_body()", "an entry of a scene's \"bodies\"");
             return w.addBody(givenKeywords(body));
           },
           "add_body(self, /, *, shape=None, shapes=None, name=None, mass=None, density=None, inertia=None, "
           "position=(0.0, 0.0, 0.0), orientation=None, velocity=(0.0, 0.0, 0.0), angular_velocity=(0.0, 0.0, 0.0), "
           "color=None, static=False, kinematic=False, forces=None, set_pose=None, springs=None, restitution=0.0, "
           "friction_static=0.6, friction_kinetic=0.5, fracture=None, sdf=None, filter=None, motion=None)\n--\n\n"
           "-> BodyId: the keys of an entry of a scene's \"bodies\" (docs/scene-format.md), e.g. "
           "shape={\"type\": \"sphere\", \"radius\": 0.25}, mass=1, position=(0, 2, 0); a compound body gives "
           "shapes=[{\"type\": \"box\", \"extents\": (1, 0.1, 1), \"position\": (0, 1, 0)}, ...] instead of shape; "
           "filter={\"category\": 2, \"mask\": 5, \"group\": -1}; a kinematic body's motion={\"pivot\": p, "
           "\"angular_velocity\": w} or {\"keyframes\": [{\"time\", \"position\", \"orientation\"}, ...], \"loop\": "
           "False}. None: the key left out (a name body<N>, mass from density 1000 kg/m^3, the World's inertia method, "
           "no rotation, the default colour)")
      .def("remove_body", [](PyWorld& w, const py::object& body) { w.removeBody(bodyArgument(body, "World.remove_body()")); },
           py::arg("body"), "remove_body(self, /, body)\n--\n\nthe last body takes the removed one's index; ids stay valid")
      .def("add_spawner",
           [](PyWorld& w, const py::args& args, const py::kwargs& spawn) {
             requireKeywordsOnly(args, "World.add_spawner()", "an entry of a scene's \"spawn\"");
             return w.addSpawner(givenKeywords(spawn));
           },
           "add_spawner(self, /, *, period, region, body=None, ragdoll=None, count=1, offsets=None, lifetime=None, "
           "seed=1, name=None, speed=None, angular_speed=None, random_orientation=True, start=0.0, end=None)\n--\n\n"
           "-> int: the spawner's index; the keys of an entry of a scene's \"spawn\" with a period [s]: count points "
           "drawn in region={\"min\": (x, y, z), \"max\": (x, y, z)} with speed=(lo, hi) [m/s] and angular_speed "
           "(lo, hi) [rad/s] by a generator seeded with seed, every period from start until end; at each point one "
           "copy per offset of offsets=[(x, y, z), ...] (default [(0, 0, 0)]), a body like body (the keys of an entry "
           "of \"bodies\" but name and pose) or a ragdoll figure like ragdoll={\"scale\", \"mass\", "
           "\"joint_friction\", \"joint_hertz\", \"joint_damping_ratio\", \"orientation\"}, named <name>_<n>; "
           "lifetime [s]: each burst removed that long after it came")
      .def_property("kill_volume", &PyWorld::killVolume, &PyWorld::setKillVolume,
                    "(min x, min y, min z, max x, max y, max z) [m] or None: bodies whose centre of mass is outside "
                    "it at the start of a step are removed (their ids go stale)")
      .def("add_plane",
           [](PyWorld& w, const py::args& args, const py::kwargs& plane) {
             requireKeywordsOnly(args, "World.add_plane()", "an entry of a scene's \"planes\"");
             return w.addPlane(givenKeywords(plane));
           },
           "add_plane(self, /, *, normal=(0.0, 1.0, 0.0), point=(0.0, 0.0, 0.0), restitution=0.0, friction_static=0.6, "
           "friction_kinetic=0.5)\n--\n\n-> int: the plane's index; the keys of an entry of a scene's \"planes\"")
      .def("add_joint",
           [](PyWorld& w, const py::args& args, const py::kwargs& joint) {
             requireKeywordsOnly(args, "World.add_joint()", "an entry of a scene's \"joints\"");
             return w.addJoint(givenKeywords(joint));
           },
           "add_joint(self, /, *, type, body_a, anchor, body_b=None, axis=None, motor=None, limits=None, cone=None, "
           "twist=None, spring=None, friction=None, linear_hertz=None, linear_damping_ratio=None, angular_hertz=None, "
           "angular_damping_ratio=None, collide_connected=False, name=None)\n--\n\n-> int: the joint's row in joints(). "
           "type \"ball\", \"hinge\", \"prismatic\" or \"weld\"; body_a, body_b: body names (body_b None: the world); "
           "anchor (x, y, z) [m]; axis (x, y, z) of a hinge, a slider, or a ball's cone and twist; "
           "motor={\"speed\": rad/s or m/s, \"max_torque\": N m (slider: \"max_force\": N)}, limits=(lo, hi) [rad] "
           "(slider: [m]); a ball's cone half-angle [rad] and twist=(lo, hi) [rad]; spring={\"hertz\": Hz, "
           "\"damping_ratio\": 1}; friction [N m] (slider: [N]); a weld's linear_/angular_hertz [Hz] and damping ratios")
      .def("add_force",
           [](PyWorld& w, const py::object& body, const py::kwargs& force) {
             w.addForce(bodyArgument(body, "World.add_force()"), givenKeywords(force));
           },
           py::arg("body"),
           "add_force(self, /, body, *, force=(0.0, 0.0, 0.0), point=(0.0, 0.0, 0.0), force_frame='world', "
           "point_frame='body', start=0.0, end=None)\n--\n\nforce [N] at point [m] on the body from start to end [s] "
           "(None: for ever); frames \"world\" or \"body\"")
      .def("set_pose",
           [](PyWorld& w, const py::object& body, const py::object& position, const py::object& orientation,
              const py::object& velocity, const py::object& angularVelocity) {
             w.setPose(bodyArgument(body, "World.set_pose()"), position, orientation, velocity, angularVelocity);
           },
           py::arg("body"), py::arg("position") = py::none(), py::arg("orientation") = py::none(),
           py::arg("velocity") = py::none(), py::arg("angular_velocity") = py::none(),
           "set_pose(self, /, body, position=None, orientation=None, velocity=None, angular_velocity=None)\n--\n\n"
           "position (x, y, z), orientation (w, x, y, z), velocity (vx, vy, vz), angular_velocity (wx, wy, wz): any of them, within a scene's ranges; the body wakes")
      .def("exact_rotation",
           [](const PyWorld& w, const py::object& body, const py::object& times) {
             return w.exactRotation(bodyArgument(body, "World.exact_rotation()"),
                                    rbsim::python::doubleArrayArgument(times, "World.exact_rotation()", "times"));
           },
           py::arg("body"), py::arg("times"),
           "exact_rotation(self, /, body, times)\n--\n\n-> (k, 4) the body's orientation (w, x, y, z) t seconds "
           "from now, for each t, by the closed-form torque-free motion (Jacobi elliptic functions): the "
           "reference for integrator errors")
      .def("step", [](PyWorld& w, const py::object& steps) { w.step(intArgument(steps, "World.step()", "steps")); },
           py::arg("steps") = 1, "step(self, /, steps=1)\n--\n\nadvance by steps x dt (other Python threads run meanwhile)")
      .def("is_valid",
           [](const PyWorld& w, const py::object& body) {
             const PyBodyId& id = bodyArgument(body, "World.is_valid()");
             return id.world == w.serial() && w.world().isValid(id.id);
           },
           py::arg("body"), "is_valid(self, /, body)\n--\n\n-> bool: the body is in this World")
      .def("index_of", [](const PyWorld& w, const py::object& body) { return w.index(bodyArgument(body, "World.index_of()"), "World.index_of()"); },
           py::arg("body"), "index_of(self, /, body)\n--\n\n-> int: the body's row in the state arrays now")
      .def("id_at",
           [](const PyWorld& w, const py::object& index) {
             const long long i = intArgument(index, "World.id_at()", "index");
             if (i < 0 || static_cast<unsigned long long>(i) >= w.world().bodies().size()) {
               throw rbsim::InputError("World.id_at()", "index",
                                       "expected a row from 0 to " + std::to_string(w.world().bodies().size()) + " - 1, got " +
                                           std::to_string(i));
             }
             return w.wrap(w.world().idAt(static_cast<std::size_t>(i)));
           },
           py::arg("index"), "id_at(self, /, index)\n--\n\n-> BodyId: the id of the body in that row")
      .def("__len__", [](const PyWorld& w) { return w.world().bodies().size(); })
      .def_property_readonly("time", [](const PyWorld& w) { return w.world().time(); }, "[s]")
      .def_property_readonly("step_count", [](const PyWorld& w) { return w.world().stepCount(); })
      .def_property_readonly("settings", [](const PyWorld& w) { return settingsDict(w.scene()); },
                             "every key of a scene's \"world\" block, as World() takes them")
      .def_property_readonly("names", [](const PyWorld& w) {
        std::vector<std::string> names;
        for (const rbsim::RigidBody& b : w.world().bodies()) names.push_back(b.name());
        return names;
      })
      .def("state_hash", [](const PyWorld& w) { return w.world().stateHash(); },
           "state_hash(self, /)\n--\n\n-> int: FNV-1a of every state's bits: equal hashes, identical runs");
  rbsim::python::bindStateArrays(world);
  rbsim::python::bindContacts(world);
  rbsim::python::bindContactEvents(world);
  rbsim::python::bindJoints(world);
  rbsim::python::bindParticles(world);
  rbsim::python::bindQueries(world);
  rbsim::python::bindWorldState(m, world);
  rbsim::python::bindChanges(world);
  rbsim::python::bindRendering(m);
  rbsim::python::bindDisk(m, world);
  rbsim::python::bindRun(m, world);
}
