// Worlds on disk from Python (issue 57): World.save_scene writes a scene file that loads back
// into the same World; rbsim.read_recording (recording_arrays.cpp) reads a recording. World.run
// and rbsim.run, which write through the program's runner, are in run_bindings.cpp.
#include <filesystem>
#include <string>

#include <pybind11/stl.h>

#include "arguments.h"
#include "py_world.h"
#include "rbsim/io/input_error.h"
#include "scene_blocks.h"

namespace py = pybind11;

namespace rbsim::python {

py::dict readRecording(const std::string& path, long long world);  // recording_arrays.cpp

namespace {

constexpr const char* kSaveCall = "World.save_scene()";
constexpr const char* kReadCall = "rbsim.read_recording()";

}  // namespace

void bindDisk(py::module_& m, py::class_<PyWorld>& world) {
  world.def(
      "save_scene",
      [](PyWorld& w, const py::object& pathArg) {
        const std::string path = pathArgument(pathArg, kSaveCall, "path");
        const nlohmann::json doc = w.blocks().document(w.world(), w.scene(), kSaveCall);
        writeTextFile(path, doc.dump(2) + "\n", kSaveCall);
      },
      py::arg("path"),
      "save_scene(self, /, path)\n--\n\nwrites the World as a scene file (docs/scene-format.md), whole or not at all: "
      "rbsim.load_scene(path).world() is this World, bit for bit before its first step; after steps the bodies' "
      "poses and velocities now (contacts' warm starts and sleep are not in a scene file)");
  m.def(
      "read_recording",
      [](const py::object& pathArg, const py::object& worldArg) {
        return readRecording(pathArgument(pathArg, kReadCall, "path"), intArgument(worldArg, kReadCall, "world"));
      },
      py::arg("path"), py::arg("world") = 0,
      "read_recording(path, world=0)\n--\n\n-> dict: world `world` (of every phase's worlds in order) of a recording "
      "(--record, World.run(record=...)), one row per recorded step: \"step\" (T,), \"time\" (T,) [s], \"x\" (T, N, 3), "
      "\"q\" (T, N, 4) (w, x, y, z), \"v\", \"omega\", \"P\", \"L\" (T, N, 3), \"awake\" (T, N); \"names\" [N], "
      "\"label\", \"worlds\" (how many), \"file\", \"overrides\", \"rbsim_version\"");
}

}  // namespace rbsim::python
