// rbsim.read_recording (issue 57): a recording (app/record/recording.h) read back by the replay's
// own code: each phase rebuilt from the scene text the recording holds, with its overrides
// (rbsim replay's way, app/main.cpp), and every entry restored into it (RecordReader::restoreNext),
// whose states are then read as the World's arrays are.
#include <algorithm>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "rbsim/io/input_error.h"
#include "record/recording.h"
#include "run/phase.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

// The rows of one world, grown step by step.
struct Rows {
  std::vector<std::uint64_t> steps;
  std::vector<double> times, x, q, v, omega, P, L;
  std::vector<std::uint8_t> awake;

  void add(const World& world) {
    steps.push_back(world.stepCount());
    times.push_back(world.time());
    for (const RigidBody& b : world.bodies()) {
      const auto put = [](std::vector<double>& out, const Vec3& a) { out.insert(out.end(), {a.x(), a.y(), a.z()}); };
      put(x, b.position());
      q.insert(q.end(), {b.orientation().w(), b.orientation().x(), b.orientation().y(), b.orientation().z()});
      put(v, b.velocity());
      put(omega, b.angularVelocity());
      put(P, b.state().linearMomentum);
      put(L, b.state().angularMomentum);
      awake.push_back(b.awake() ? 1 : 0);
    }
  }
};

template <class T>
py::array_t<T> array(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace

py::dict readRecording(const std::string& path, long long world) {
  constexpr const char* kCall = "rbsim.read_recording()";
  app::RecordReader reader(path);  // InputError naming the file: unreadable, not a recording, another version
  const std::vector<std::string>& overrides = reader.header().overrides;
  std::vector<app::Phase> phases;
  std::size_t worldCount = 0;
  for (std::size_t i = 0; i < reader.header().phases.size(); ++i) {
    const app::RecordedPhase& p = reader.header().phases[i];
    reader.checkFiles(i);
    phases.push_back(app::parsePhaseText(p.text, p.file, p.baseDir, overrides));
    worldCount += phases.back().worlds.size();
  }
  if (world < 0 || static_cast<unsigned long long>(world) >= worldCount) {
    throw InputError(kCall, "world", "expected a world from 0 to " + std::to_string(worldCount) + " - 1 (the recording holds " +
                                         std::to_string(worldCount) + "), got " + std::to_string(world));
  }
  Rows rows;
  std::vector<std::string> names;
  std::string label, file;
  std::size_t first = 0;  // the number of the phase's first world among all
  {
    py::gil_scoped_release release;  // reading and inflating touch no Python object
    for (const app::Phase& phase : phases) {
      std::vector<World> worlds;
      for (const app::PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
      const std::size_t chosen = static_cast<std::size_t>(world) - first;
      const bool here = static_cast<std::size_t>(world) >= first && chosen < worlds.size();
      if (here) {
        for (const RigidBody& b : worlds[chosen].bodies()) names.push_back(b.name());
        label = phase.worlds[chosen].label;
        file = phase.file;
      }
      // A step of each world in turn: the order in which the program records a compared phase's
      // worlds at one step per frame; any other is read ahead (RecordReader's pending entries).
      std::uint64_t longest = 0;
      for (const app::PhaseWorld& w : phase.worlds) longest = std::max(longest, w.scene.stepCount());
      for (std::uint64_t s = 1; s <= longest; ++s) {
        for (std::size_t k = 0; k < worlds.size(); ++k) {
          if (s > phase.worlds[k].scene.stepCount()) continue;
          reader.restoreNext(k, worlds.size(), worlds[k]);
          // The arrays hold one set of bodies, the scene's (N fixed).
          if (here && k == chosen && reader.bodiesChanged(k)) {
            throw InputError(path, "world", "world " + std::to_string(world) + "'s bodies change at step " + std::to_string(s) +
                                                " (spawned, removed or broken), and the arrays hold one set of bodies for "
                                                "every step: read it with `rbsim replay FILE --trace T.csv` instead");
          }
          if (here && k == chosen) rows.add(worlds[k]);
        }
      }
      first += worlds.size();
    }
    reader.expectEnd();  // InputError when the file holds more than its scenes run
  }
  const auto T = static_cast<py::ssize_t>(rows.steps.size());
  const auto N = static_cast<py::ssize_t>(names.size());
  py::dict d;
  d["step"] = array(rows.steps, {T});
  d["time"] = array(rows.times, {T});
  d["x"] = array(rows.x, {T, N, 3});
  d["q"] = array(rows.q, {T, N, 4});
  d["v"] = array(rows.v, {T, N, 3});
  d["omega"] = array(rows.omega, {T, N, 3});
  d["P"] = array(rows.P, {T, N, 3});
  d["L"] = array(rows.L, {T, N, 3});
  d["awake"] = array(rows.awake, {T, N}).attr("astype")("bool");
  d["names"] = names;
  d["label"] = label;
  d["worlds"] = worldCount;
  d["file"] = file;
  d["overrides"] = overrides;
  d["rbsim_version"] = reader.header().rbsimVersion;
  return d;
}

}  // namespace rbsim::python
