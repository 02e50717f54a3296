#pragma once
// The fuzz targets' common end: parse a scene (with --set assignments), then step a small world.
// Bad input may only end in InputError (exit 2 in the app) or, once running, SimulationError;
// anything else escapes, and libFuzzer (or the replay test) stops on it.
#include <cstddef>
#include <string>
#include <vector>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim::fuzz {

// Stepping is what finds NaN and overflow in the engine, but a fuzzed scene of many bodies would
// spend the time budget on one input: small worlds only, a few steps each.
inline constexpr std::size_t kMaxSteppedBodies = 16;
inline constexpr int kSteps = 8;

inline void parseAndStep(const std::string& text, const std::string& baseDir,
                         const std::vector<std::string>& overrides = {}) {
  try {
    const Scene scene = parseSceneText(text, "fuzz.json", baseDir, overrides);
    if (scene.bodies.size() > kMaxSteppedBodies) return;
    World world = buildWorld(scene);
    for (int i = 0; i < kSteps; ++i) world.step();
  } catch (const InputError&) {
  } catch (const SimulationError&) {
  }
}

}  // namespace rbsim::fuzz
