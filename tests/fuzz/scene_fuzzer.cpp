// Fuzz target: the scene loader on arbitrary text, then a few steps of the world it describes.
// Bad input may only ever end in InputError (exit 2 in the app) or, once running, SimulationError;
// any other exception, a crash or a sanitizer report is a bug (libFuzzer stops on each).
#include <cstdint>
#include <string>

#include "step_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Mesh paths resolve against the demo scenes' folder, so "../meshes/t_handle.obj" loads.
  rbsim::fuzz::parseAndStep(std::string(reinterpret_cast<const char*>(data), size), RBSIM_FUZZ_SCENE_DIR);
  return 0;
}
