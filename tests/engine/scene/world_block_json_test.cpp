// worldBlockJson writes back what parseWorldBlock reads: for the defaults, and for a block that
// gives every key a value other than its default (so a key the writer forgot, or wrote from the
// wrong field, fails here).
#include <gtest/gtest.h>

#include <string>

#include "rbsim/scene/scene_parts.h"

namespace rbsim::test {
namespace {

Scene parsed(const nlohmann::json& block) {
  Scene scene;
  parseWorldBlock(JsonObject(block, "test.json", "world", kWorldKeys), scene);
  return scene;
}

TEST(WorldBlockJson, NamesEveryKeyButSteps) {
  const nlohmann::json written = worldBlockJson(Scene{});
  for (const char* key : kWorldKeys) EXPECT_EQ(written.contains(key), std::string(key) != "steps") << key;
  EXPECT_EQ(written.size(), kWorldKeys.size() - 1);
}

TEST(WorldBlockJson, TheDefaultsReadBackAsTheDefaults) {
  const nlohmann::json written = worldBlockJson(Scene{});
  EXPECT_EQ(worldBlockJson(parsed(written)), written);
}

TEST(WorldBlockJson, EveryKeyChangedReadsBackAsWritten) {
  const nlohmann::json changed = {
      {"gravity", {1.0, -3.0, 0.5}}, {"dt", 0.01}, {"integrator", "euler-matrix"}, {"drift_correction", false}, {"inertia", "cube"}, {"duration", 2.5},
      {"sleep", false}, {"sleep_linear_speed", 0.02}, {"sleep_angular_speed", 0.03}, {"time_to_sleep", 0.7},
      {"collisions", false}, {"ccd", false}, {"ccd_motion_fraction", 0.3}, {"broad_phase", "brute-force"},
      {"contact_margin", 0.03}, {"contact_recycle_distance", 0.002}, {"solver", "pgs"}, {"friction", "seed000"}, {"mesh_contact", "triangles"},
      {"substeps", 7}, {"contact_hertz", 45.0}, {"contact_damping_ratio", 3.0}, {"contact_push_speed", 2.5},
      {"velocity_iterations", 13}, {"position_iterations", 5}, {"restitution_threshold", 0.4}, {"hit_event_speed", 3.0}, {"contact_slop", 0.007},
      {"position_correction", 0.3}, {"warm_starting", false}, {"warm_start_distance", 0.04}, {"response", false},
      {"log_queries", true}, {"query_log_capacity", 123}, {"skip_idle_stages", false}, {"threads", 3},
      {"particle_integrator", "explicit-euler"}};
  ASSERT_EQ(changed.size(), kWorldKeys.size() - 1);
  const nlohmann::json defaults = worldBlockJson(Scene{});
  for (const auto& [key, value] : changed.items()) EXPECT_NE(defaults.at(key), value) << key << " is its default";
  EXPECT_EQ(worldBlockJson(parsed(changed)), changed);
}

}  // namespace
}  // namespace rbsim::test
