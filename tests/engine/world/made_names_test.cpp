// The names the World makes while it steps (world/made_names.h, issue 56, item 4): every name a
// spawner makes is one its pattern admits and no other spawner's does, and a scene whose spawners,
// ragdolls and bodies would share a name is refused at load.
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/made_names.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

// Three spawners whose names are prefixes of each other's: rain (boxes), rain_1 (boxes) and
// rain_2 (ragdolls), with a listed ragdoll rain_1_0 beside them, over 1.2 s.
nlohmann::json prefixScene() {
  const auto spawner = [](const char* name, double x, bool ragdoll) {
    nlohmann::json s = {{"name", name}, {"period", 0.25}, {"lifetime", 0.6},
                        {"region", {{"min", {x, 3, 0}}, {"max", {x + 1, 4, 1}}}}};
    if (ragdoll) {
      s["ragdoll"] = nlohmann::json::object();
      s["random_orientation"] = false;
    } else {
      s["body"] = {{"shape", {{"type", "box"}, {"extents", {0.2, 0.2, 0.2}}}}, {"mass", 1}};
    }
    return s;
  };
  return {{"world", {{"dt", 1.0 / 60.0}, {"duration", 1.2}}},
          {"planes", {{{"normal", {0, 1, 0}}, {"point", {0, 0, 0}}}}},
          {"spawn", {spawner("rain", 0, false), spawner("rain_1", 3, false), spawner("rain_2", 6, true)}},
          {"ragdolls", {{{"name", "rain_1_0"}, {"position", {-4, 0, 0}}}}}};
}

TEST(MadeNames, EveryNameASpawnerMakesIsItsAloneAndNoneRepeats) {
  const Scene scene = parseScene(prefixScene(), "prefix.json", "");
  World world = buildWorld(scene);
  std::map<std::string, int> seen;  // every name ever made, and how many bodies had it at once
  for (std::uint64_t step = 0; step < scene.stepCount(); ++step) {
    world.step();
    std::set<std::string> now;
    for (const RigidBody& body : world.bodies()) {
      ASSERT_TRUE(now.insert(body.name()).second) << "two bodies named " << body.name() << " at step " << step;
      ++seen[body.name()];
    }
  }
  int made = 0;
  for (const auto& [name, count] : seen) {
    int makers = 0;
    for (const Spawner& spawner : spawners(world)) makers += spawnerMakesName(spawner.def, name) ? 1 : 0;
    const bool listed = name.rfind("rain_1_0_", 0) == 0;  // the listed ragdoll's bones
    EXPECT_EQ(makers, listed ? 0 : 1) << name;
    made += listed ? 0 : 1;
  }
  // Five bursts each (t = 0, 0.25, ..., 1.0): 5 + 5 boxes and 5 x 11 bones.
  EXPECT_EQ(made, 5 + 5 + 5 * static_cast<int>(kBoneCount));
}

TEST(MadeNames, APatternAdmitsItsOwnNamesOnly) {
  SpawnerDef boxes;
  boxes.name = "rain";
  SpawnerDef figures;
  figures.name = "fig";
  figures.ragdoll = RagdollDef{};
  EXPECT_TRUE(spawnerMakesName(boxes, "rain_0"));
  EXPECT_TRUE(spawnerMakesName(boxes, "rain_12345678901234567890"));
  for (const char* name : {"rain", "rain_", "rain_x", "rain_1_pelvis", "rain_-1", "rain_1 ", "rainy_1", "rain__1"}) {
    EXPECT_FALSE(spawnerMakesName(boxes, name)) << name;
  }
  for (const std::string& bone : ragdollBodyNames("fig_7")) EXPECT_TRUE(spawnerMakesName(figures, bone)) << bone;
  for (const char* name : {"fig_7", "fig_7_", "fig_7_knee", "fig_x_pelvis", "fig_pelvis", "fig_7_pelvis_0"}) {
    EXPECT_FALSE(spawnerMakesName(figures, name)) << name;
  }
  EXPECT_EQ(ragdollBodyNames("left")[static_cast<std::size_t>(Bone::Head)], "left_head");
  EXPECT_EQ(freeSpawnerName([](const std::string& n) { return n == "spawn" || n == "spawn1"; }), "spawn2");
}

TEST(MadeNames, AScenesNamesThatASpawnerWouldRepeatAreRefused) {
  nlohmann::json doc = prefixScene();
  doc["bodies"] = {{{"name", "rain_4"}, {"shape", {{"type", "sphere"}, {"radius", 0.1}}}, {"mass", 1}}};
  try {
    static_cast<void>(parseScene(doc, "prefix.json", ""));
    FAIL() << "rain_4 was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "bodies[0].name");
    EXPECT_NE(e.problem().find("the spawner \"rain\""), std::string::npos) << e.what();
  }
  doc["bodies"][0]["name"] = "rain_4_x";  // no spawner's: rain_4_x is neither NAME_k nor NAME_k_bone
  EXPECT_NO_THROW(static_cast<void>(parseScene(doc, "prefix.json", "")));
  doc["bodies"][0]["name"] = "rain_2_3_lower_leg_left";
  EXPECT_THROW(static_cast<void>(parseScene(doc, "prefix.json", "")), InputError);
}

}  // namespace
}  // namespace rbsim
