// Fuzz target: the scene loader on arbitrary text, then a few steps of the world it describes.
// Bad input may only ever end in InputError (exit 2 in the app) or, once running, SimulationError;
// any other exception, a crash or a sanitizer report is a bug (libFuzzer stops on each).
#include <cstdint>
#include <string>

#include "io/input_error.h"
#include "scene/scene.h"
#include "world/simulation_error.h"

namespace {

// Stepping is what finds NaN and overflow in the engine, but a fuzzed scene of many bodies would
// spend the time budget on one input: small worlds only, a few steps each.
constexpr std::size_t kMaxSteppedBodies = 16;
constexpr int kSteps = 8;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // Mesh paths resolve against the demo scenes' folder, so "../meshes/t_handle.obj" loads.
    const rbsim::Scene scene = rbsim::parseSceneText(text, "fuzz.json", RBSIM_FUZZ_SCENE_DIR);
    if (scene.bodies.size() > kMaxSteppedBodies) return 0;
    rbsim::World world = rbsim::buildWorld(scene);
    for (int i = 0; i < kSteps; ++i) world.step();
  } catch (const rbsim::InputError&) {
  } catch (const rbsim::SimulationError&) {
  }
  return 0;
}
