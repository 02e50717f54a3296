// Every field of Settings (engine/include/rbsim/settings/settings.h) is a "world" key of a scene and of
// `--set world.KEY=VALUE`, reaches the World, and a value out of range is refused by the one check
// (checkSettings) with one message: "world.KEY: expected ...", from a file as from C++.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"
#include "test_util.h"

namespace rbsim {
namespace {

struct Key {
  std::string name;       // under "world"
  std::string value;      // a valid value unlike the default, as --set writes it
  std::function<bool(const Settings&)> reached;  // the field has the value
  std::string bad;        // a value checkSettings refuses ("" for booleans and names)
  std::string with{};     // another key's assignment the value needs, as --set writes it ("" for none)
};

const std::vector<Key>& keys() {
  static const std::vector<Key> all = {
      {"gravity", "[0,-1.62,0]", [](const Settings& s) { return s.gravity.y() == -1.62; }, "[0,0,1e14]"},
      {"dt", "0.01", [](const Settings& s) { return s.timeStep == 0.01; }, "0.5"},
      {"integrator", "rk4", [](const Settings& s) { return s.integrator == Integrator::Rk4; }, ""},
      {"drift_correction", "false", [](const Settings& s) { return !s.driftCorrection; }, "", "world.integrator=euler-matrix"},
      {"inertia", "cube", [](const Settings& s) { return s.inertia == InertiaMethod::Cube; }, ""},
      {"sleep", "false", [](const Settings& s) { return !s.allowSleep; }, ""},
      {"sleep_linear_speed", "0.02", [](const Settings& s) { return s.sleepLinearSpeed == 0.02; }, "-1"},
      {"sleep_angular_speed", "0.1", [](const Settings& s) { return s.sleepAngularSpeed == 0.1; }, "-1"},
      {"time_to_sleep", "2", [](const Settings& s) { return s.timeToSleep == 2.0; }, "0"},
      {"collisions", "false", [](const Settings& s) { return !s.detectCollisions; }, ""},
      {"broad_phase", "brute-force", [](const Settings& s) { return s.broadPhase == Settings::BroadPhaseMethod::BruteForce; }, ""},
      {"contact_margin", "0.02", [](const Settings& s) { return s.contactMargin == 0.02; }, "2"},
      {"contact_recycle_distance", "0.003", [](const Settings& s) { return s.contactRecycleDistance == 0.003; }, "-2"},
      {"contact_recycle_distance", "0", [](const Settings& s) { return s.contactRecycleDistance == 0.0; }, "often"},
      {"ccd", "false", [](const Settings& s) { return !s.continuousCollision; }, ""},
      {"ccd_motion_fraction", "0.5", [](const Settings& s) { return s.ccdMotionFraction == 0.5; }, "0"},
      {"log_queries", "true", [](const Settings& s) { return s.logQueries; }, ""},
      {"query_log_capacity", "64", [](const Settings& s) { return s.queryLogCapacity == 64; }, "0"},
      {"response", "false", [](const Settings& s) { return !s.respondToContacts; }, ""},
      {"solver", "pgs", [](const Settings& s) { return s.solver == Settings::ContactSolverMethod::Pgs; }, ""},
      {"friction", "seed000", [](const Settings& s) { return s.friction == Settings::FrictionModel::Seed000; }, ""},
      {"mesh_contact", "triangles", [](const Settings& s) { return s.meshContact == Settings::MeshContact::Triangles; }, ""},
      {"substeps", "4", [](const Settings& s) { return s.substeps == 4; }, "65"},
      {"contact_hertz", "60", [](const Settings& s) { return s.contactHertz == 60.0; }, "-1"},
      {"contact_damping_ratio", "1", [](const Settings& s) { return s.contactDampingRatio == 1.0; }, "-1"},
      {"contact_push_speed", "1", [](const Settings& s) { return s.contactPushSpeed == 1.0; }, "0"},
      {"velocity_iterations", "20", [](const Settings& s) { return s.velocityIterations == 20; }, "1001"},
      {"position_iterations", "2", [](const Settings& s) { return s.positionIterations == 2; }, "-1"},
      {"restitution_threshold", "0", [](const Settings& s) { return s.restitutionThreshold == 0.0; }, "-1"},
      {"hit_event_speed", "2.5", [](const Settings& s) { return s.hitEventSpeed == 2.5; }, "-1"},
      {"contact_slop", "0.001", [](const Settings& s) { return s.contactSlop == 0.001; }, "2"},
      {"position_correction", "0.5", [](const Settings& s) { return s.positionCorrection == 0.5; }, "1.5"},
      {"warm_starting", "false", [](const Settings& s) { return !s.warmStarting; }, ""},
      {"warm_start_distance", "0.05", [](const Settings& s) { return s.warmStartDistance == 0.05; }, "-1"},
      {"skip_idle_stages", "false", [](const Settings& s) { return !s.skipIdleStages; }, ""},
  };
  return all;
}

class SettingsKeys : public testing::Test {
 protected:
  void SetUp() override {
    path_ = test::uniqueTempName("settings_keys") + ".json";
    std::ofstream(path_) << R"({"bodies": [{"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1}]})";
  }
  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_;
};

// The default of each key is not the value tried, so reaching the World shows the key was read.
TEST_F(SettingsKeys, EveryFieldIsSetByItsKeyAndReachesTheWorld) {
  for (const Key& k : keys()) {
    ASSERT_FALSE(k.reached(Settings{})) << k.name << ": the value tried is the default";
    std::vector<std::string> overrides = {"world." + k.name + "=" + k.value};
    if (!k.with.empty()) overrides.push_back(k.with);
    const Scene scene = loadScene(path_, overrides);
    EXPECT_TRUE(k.reached(scene.settings)) << k.name;
    const World world = buildWorld(scene);
    EXPECT_TRUE(k.reached(world.settings())) << k.name;
  }
}

TEST_F(SettingsKeys, ABadValueIsRefusedWithTheSameWordsFromAFileAndFromCpp) {
  int tried = 0;
  for (const Key& k : keys()) {
    if (k.bad.empty()) continue;
    ++tried;
    try {
      loadScene(path_, {"world." + k.name + "=" + k.bad});
      ADD_FAILURE() << k.name << "=" << k.bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "world." + k.name);
      EXPECT_EQ(e.problem().rfind("expected", 0), 0u) << e.what();
    }
  }
  EXPECT_GE(tried, 18);
  // A World given a bad value in C++ says it in the same words as the scene loader.
  Settings s;
  s.ccdMotionFraction = 0.0;
  try {
    World world(s);
    ADD_FAILURE() << "ccd_motion_fraction = 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), checkSettings(s).message());
    EXPECT_EQ(std::string(e.what()).rfind("world.ccd_motion_fraction: expected", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace rbsim
