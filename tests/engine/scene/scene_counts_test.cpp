// Scene::mostBodiesAtOnce (issue 56, item 1), against the World it builds: the budgets of a run's
// outputs count every body the scene makes, so the bound must hold at every step, and be the count
// itself where nothing is removed early.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

nlohmann::json countedScene(double lifetime) {
  nlohmann::json boxes = {{"name", "box"}, {"count", 3}, {"period", 0.1}, {"start", 0.05}, {"end", 0.72},
                          {"region", {{"min", {0, 2, 0}}, {"max", {4, 3, 4}}}},
                          {"body", {{"shape", {{"type", "box"}, {"extents", {0.2, 0.2, 0.2}}}}, {"mass", 1}}}};
  nlohmann::json figures = {{"name", "fig"}, {"period", 0.25}, {"offsets", {{0, 0, 0}, {2, 0, 0}}},
                            {"ragdoll", nlohmann::json::object()}, {"region", {{"min", {-6, 2, 0}}, {"max", {-6, 2, 0}}}}};
  if (lifetime > 0.0) {
    boxes["lifetime"] = lifetime;
    figures["lifetime"] = lifetime;
  }
  return {{"world", {{"dt", 1.0 / 60.0}, {"duration", 1.0}}},
          {"planes", {{{"normal", {0, 1, 0}}, {"point", {0, 0, 0}}}}},
          {"bodies", {{{"name", "crate"}, {"shape", {{"type", "box"}, {"extents", {1, 1, 1}}}}, {"mass", 1}, {"position", {8, 0.5, 0}}}}},
          {"ragdolls", {{{"name", "solo"}, {"position", {-10, 0, 0}}}}},
          {"spawn", {boxes, figures, {{"name", "pile"}, {"count", 4}, {"region", {{"min", {10, 1, 0}}, {"max", {12, 2, 2}}}},
                                      {"body", {{"shape", {{"type", "sphere"}, {"radius", 0.2}}}, {"mass", 1}}}}}}};
}

std::size_t mostAtOnce(const Scene& scene) {
  World world = buildWorld(scene);
  std::size_t most = world.bodies().size();
  for (std::uint64_t i = 0; i < scene.stepCount(); ++i) {
    world.step();
    most = std::max(most, world.bodies().size());
  }
  return most;
}

TEST(SceneCounts, TheMostBodiesAtOnceIsWhatTheWorldHolds) {
  // Nothing removed: 1 crate + 4 spheres + 11 bones listed; boxes at 0.05, 0.15, ..., 0.65 s (7
  // bursts of 3); figures at 0, 0.25, 0.5, 0.75, 1.0 s (5 bursts of 2 x 11) within the second.
  const Scene kept = parseScene(countedScene(0.0), "counted.json", "");
  const double expected = 1 + 4 + 11 + 7 * 3 + 5 * 2 * 11;
  EXPECT_EQ(kept.mostBodiesAtOnce(), expected);
  // The last figures' burst at t = 1.0 s comes with step 61, after the run: the bound is not tight.
  EXPECT_EQ(static_cast<double>(mostAtOnce(kept)), expected - 2 * 11);
}

TEST(SceneCounts, ALifetimeBoundsTheBurstsAliveAtOnce) {
  const Scene removed = parseScene(countedScene(0.3), "counted.json", "");
  // ceil(0.3 / 0.1) + 1 = 4 bursts of boxes and ceil(0.3 / 0.25) + 1 = 3 of figures at once.
  EXPECT_EQ(removed.mostBodiesAtOnce(), 1 + 4 + 11 + 4 * 3 + 3 * 2 * 11);
  EXPECT_LE(static_cast<double>(mostAtOnce(removed)), removed.mostBodiesAtOnce());
}

}  // namespace
}  // namespace rbsim
