// Fuzz target: the --set override parser (applyOverride) on arbitrary assignments applied to a
// valid scene, then the scene check and a few steps of the world, as `rbsim run FILE --set ...`
// does. Input: the first byte picks the base scene ('0' valid.json, '1' a mesh scene, '2'
// particles, '3' a soft body, '4' the 2D world; other bytes wrap around), an optional newline,
// then one assignment per line. Only InputError (and, once running, SimulationError) may come out;
// any other exception, a crash or a sanitizer report is a bug (libFuzzer stops on each).
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "step_scene.h"

namespace {

// The app takes any number of --set flags; beyond a handful they only overwrite each other.
constexpr std::size_t kMaxAssignments = 8;

struct BaseScene {
  std::string text;
  std::string dir;  // mesh paths resolve against the scene's own folder
};

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

const std::vector<BaseScene>& baseScenes() {
  static const std::vector<BaseScene> scenes = [] {
    const std::string demos = RBSIM_FUZZ_SCENE_DIR;
    const std::string bad = RBSIM_FUZZ_BAD_DIR;
    std::vector<BaseScene> out;
    out.push_back({readText(bad + "/valid.json"), bad});
    for (const char* name : {"assignment2_d_mesh_inertia.json", "particles_fountain.json", "soft_jelly.json",
                             "planar_tumbling.json"}) {
      out.push_back({readText(demos + "/" + name), demos});
    }
    return out;
  }();
  return scenes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::vector<BaseScene>& scenes = baseScenes();
  const BaseScene& base = scenes[static_cast<std::uint8_t>(data[0] - '0') % scenes.size()];
  std::size_t start = (size > 1 && data[1] == '\n') ? 2 : 1;
  const std::string text(reinterpret_cast<const char*>(data) + start, size - start);
  std::vector<std::string> overrides;
  std::size_t from = 0;
  while (from <= text.size() && overrides.size() < kMaxAssignments) {
    std::size_t end = text.find('\n', from);
    if (end == std::string::npos) end = text.size();
    overrides.push_back(text.substr(from, end - from));
    from = end + 1;
  }
  rbsim::fuzz::parseAndStep(base.text, base.dir, overrides);
  return 0;
}
