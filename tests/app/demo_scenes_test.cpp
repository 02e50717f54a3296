// Every phase of every numbered demo loads from assets/scenes/ and simulates a second without
// the state leaving finite values, and runs the same twice (the determinism hash).
#include <cmath>

#include <gtest/gtest.h>

#include "demos/demo.h"
#include "paths.h"
#include "scene/scene.h"
#include "world/world.h"

namespace rbsim::app {
namespace {

TEST(DemoScenes, EveryPhaseLoadsSimulatesAndRepeatsBitForBit) {
  int phases = 0;
  for (const Demo& demo : allDemos()) {
    for (const std::string& file : demo.scenes) {
      const Scene scene = loadScene(assetDir() + "/scenes/" + file);
      World first = buildWorld(scene), second = buildWorld(scene);
      const int steps = static_cast<int>(std::lround(1.0 / scene.settings.timeStep));
      for (int s = 0; s < steps; ++s) {
        first.step();
        second.step();
      }
      EXPECT_EQ(first.stateHash(), second.stateHash()) << file;
      for (const RigidBody& b : first.bodies()) EXPECT_TRUE(b.position().allFinite()) << file << " " << b.name();
      ++phases;
    }
  }
  EXPECT_GE(phases, 12);
}

}  // namespace
}  // namespace rbsim::app
