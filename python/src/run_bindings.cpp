// World.run and rbsim.run (issue 57): the program's trace, recording and glTF, written through
// its own runner (app/run/runner.h runPhases), so a file is byte for byte what `rbsim run` writes
// for the same scene. The runner draws frames too, so these live in the rendering module alone
// (python/CMakeLists.txt); the physics-only one binds them from render_off.cpp as absent.
#include <filesystem>
#include <string>

#include <pybind11/stl.h>

#include "arguments.h"
#include "py_world.h"
#include "rbsim/io/input_error.h"
#include "run/phase.h"
#include "run/run_options.h"
#include "run/runner.h"
#include "run/scene_catalogue.h"
#include "scene_blocks.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

constexpr const char* kRunCall = "World.run()";
constexpr const char* kModuleRunCall = "rbsim.run()";

// The outputs' keyword arguments, as the program's flags: an empty path writes nothing.
app::RunOptions outputOptions(const py::object& trace, const py::object& traceEvery, const py::object& record,
                              const py::object& gltf, const char* call) {
  app::RunOptions options;
  options.render = false;
  options.quiet = true;
  if (!trace.is_none()) options.tracePath = pathArgument(trace, call, "trace");
  if (!record.is_none()) options.recordPath = pathArgument(record, call, "record");
  if (!gltf.is_none()) options.gltfPath = pathArgument(gltf, call, "gltf");
  const long long every = intArgument(traceEvery, call, "trace_every");
  if (every < 1) throw InputError(call, "trace_every", "expected a number of steps >= 1, got " + std::to_string(every));
  options.traceEvery = static_cast<std::uint64_t>(every);
  return options;
}

py::dict summaryDict(const app::RunSummary& s) {
  py::dict d;
  d["steps"] = s.steps;
  d["record_bytes"] = s.recordBytes;
  d["record_body_steps"] = s.recordBodySteps;
  d["gltf_bodies"] = s.gltfBodies;
  d["gltf_frames"] = s.gltfFrames;
  return d;
}

// The phase World.run runs: the World's scene, its duration the steps to reach. A recording and a
// glTF describe the run from step 0 of the scene file the World would be saved as (its text goes
// into the recording, as a scene file's does), so they need a World at step 0 built in Python.
app::Phase worldPhase(const PyWorld& w, std::uint64_t target, const app::RunOptions& options) {
  const World& world = w.world();
  const bool fromStart = !options.recordPath.empty() || !options.gltfPath.empty();
  if (fromStart && world.stepCount() != 0) {
    throw InputError(kRunCall, options.recordPath.empty() ? "gltf" : "record",
                     "a recording or a glTF holds a run from step 0, and the World has run " +
                         std::to_string(world.stepCount()) + " steps (get_state before the first step, or save_scene then)");
  }
  const bool loaded = w.scene().file != "World()";
  if (!options.recordPath.empty() && loaded) {
    throw InputError(kRunCall, "record", "this World was loaded from " + w.scene().file +
                                             ": rbsim.run(file, overrides, record=...) records its scene with the overrides");
  }
  Scene scene = w.scene();
  scene.settings = world.settings();
  if (fromStart && !loaded) {
    nlohmann::json doc = w.blocks().document(world, scene, kRunCall);
    doc["world"].erase("duration");
    doc["world"]["steps"] = target;
    const std::string text = doc.dump(2) + "\n";
    app::Phase phase = app::parsePhaseText(text, kRunCall, std::filesystem::current_path().string());
    phase.text = text;
    return phase;
  }
  scene.duration = static_cast<double>(target) * scene.settings.timeStep;
  return app::singleWorldPhase(std::move(scene));
}

}  // namespace

void bindRun(py::module_& m, py::class_<PyWorld>& world) {
  world.def(
      "run",
      [](PyWorld& w, const py::object& stepsArg, const py::object& trace, const py::object& traceEvery,
         const py::object& record, const py::object& gltf) {
        const long long steps = intArgument(stepsArg, kRunCall, "steps");
        if (steps < 1) throw InputError(kRunCall, "steps", "expected a number of steps >= 1, got " + std::to_string(steps));
        const app::RunOptions options = outputOptions(trace, traceEvery, record, gltf, kRunCall);
        const app::Phase phase = worldPhase(w, w.world().stepCount() + static_cast<std::uint64_t>(steps), options);
        app::RunSummary summary;
        w.runOnWorld([&](World& world) { summary = app::runPhases({phase}, options, "", {}, nullptr, &world); });
        return summaryDict(summary);
      },
      py::arg("steps"), py::kw_only(), py::arg("trace") = py::none(), py::arg("trace_every") = 1,
      py::arg("record") = py::none(), py::arg("gltf") = py::none(),
      "run(self, /, steps, *, trace=None, trace_every=1, record=None, gltf=None)\n--\n\n-> dict: steps the World as "
      "`rbsim run` steps a scene, writing what its --trace, --trace-every, --record and --gltf write (the same "
      "bytes); record and gltf from step 0, at the scene's view.fps; {\"steps\", \"record_bytes\", "
      "\"record_body_steps\", \"gltf_bodies\", \"gltf_frames\"}");
  m.def(
      "run",
      [](const py::object& pathArg, const py::object& overridesArg, const py::object& trace, const py::object& traceEvery,
         const py::object& record, const py::object& gltf) {
        const std::string given = pathArgument(pathArg, kModuleRunCall, "path");
        app::RunOptions options = outputOptions(trace, traceEvery, record, gltf, kModuleRunCall);
        options.overrides = stringListArgument(overridesArg, kModuleRunCall, "overrides");
        const std::vector<app::Phase> phases{app::loadPhase(app::resolveScene(given), options.overrides)};
        app::RunSummary summary;
        {
          py::gil_scoped_release release;  // the run touches no Python object
          summary = app::runPhases(phases, options, "");
        }
        return summaryDict(summary);
      },
      py::arg("path"), py::arg("overrides") = py::list(), py::kw_only(), py::arg("trace") = py::none(),
      py::arg("trace_every") = 1, py::arg("record") = py::none(), py::arg("gltf") = py::none(),
      "run(path, overrides=(), *, trace=None, trace_every=1, record=None, gltf=None)\n--\n\n-> dict: `rbsim run path "
      "--no-render --set ...` with its --trace, --trace-every, --record and --gltf: the same files; "
      "{\"steps\", \"record_bytes\", \"record_body_steps\", \"gltf_bodies\", \"gltf_frames\"}");
}

}  // namespace rbsim::python
