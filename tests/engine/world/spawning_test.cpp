// Bodies born and removed while the World steps (world/spawner.h): bursts at their times with the
// seeded draws, a kill volume removing what falls out, ids of removed bodies never naming a body
// again, and the scene's periodic "spawn" blocks and "kill_volume".
#include <cmath>
#include <functional>
#include <set>

#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

SpawnerDef ballRain() {
  SpawnerDef def;
  def.name = "ball";
  def.prototype = shapeBodyDef(Shape::sphere(0.1), 1.0);
  def.count = 3;
  def.start = 0.5;
  def.period = 0.25;
  def.end = 1.5;
  def.regionMin = Vec3(-1, 5, -1);
  def.regionMax = Vec3(1, 6, 1);
  def.speedMax = 2.0;
  return def;
}

class Spawning : public testing::TestWithParam<double> {
 protected:
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam();
    return s;
  }
};

// Bursts at 0.5, 0.75, 1.0 and 1.25 s (none at the end, 1.5 s): 3 bodies each, in the region,
// no faster than the speed range, named ball_0 ... ball_11 in turn.
TEST_P(Spawning, BurstsComeAtTheirTimesWithTheirCount) {
  World w(settings());
  addSpawner(w, ballRain());
  std::vector<double> burstTimes;
  while (w.time() < 2.0) {
    const double t = w.time();
    w.step();
    if (!spawnedBodies(w).empty()) {
      burstTimes.push_back(t);
      EXPECT_EQ(spawnedBodies(w).size(), 3u);
      for (const BodyId id : spawnedBodies(w)) {
        const RigidBody& b = w.body(id);
        // Drawn in the region at the step's start, then moved by one step: within |v| dt + g dt^2.
        const double slack = 2.0 * GetParam() + 9.81 * GetParam() * GetParam();
        EXPECT_TRUE((b.position().array() >= Vec3(-1, 5, -1).array() - slack).all()) << b.position().transpose();
        EXPECT_TRUE((b.position().array() <= Vec3(1, 6, 1).array() + slack).all()) << b.position().transpose();
      }
    }
  }
  ASSERT_EQ(burstTimes.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(burstTimes[k], 0.5 + 0.25 * k, 0.5 * GetParam());
  EXPECT_EQ(w.bodies().size(), 12u);
  EXPECT_EQ(w.bodies().back().name(), "ball_11");
}

// The same seed gives the same bodies in the same places, however many steps a burst falls in.
TEST_P(Spawning, TheSeedDecidesTheDraws) {
  World a(settings()), b(settings()), c(settings());
  addSpawner(a, ballRain());
  addSpawner(b, ballRain());
  SpawnerDef other = ballRain();
  other.seed = 2;
  addSpawner(c, other);
  for (int i = 0; i < static_cast<int>(1.0 / GetParam()); ++i) {
    a.step();
    b.step();
    c.step();
  }
  EXPECT_EQ(a.stateHash(), b.stateHash());
  EXPECT_NE(a.stateHash(), c.stateHash());
}

// Balls falling past the kill volume's floor are removed at the next step's start; their ids go
// stale and never name a body again, though later bodies reuse their slots.
TEST_P(Spawning, TheKillVolumeRemovesWhatFallsOutAndItsIdsStayStale) {
  World w(settings());
  SpawnerDef rain = ballRain();
  rain.end = 3.0;
  addSpawner(w, rain);
  // A static shelf whose centre lies outside the volume stays: it never leaves it (issue 56, item 5).
  BodyDef shelf = shapeBodyDef(Shape::box(Vec3(2, 0.1, 2)), 1.0, "shelf");
  shelf.isStatic = true;
  shelf.position = Vec3(30, 2, 0);
  const BodyId shelfId = w.addBody(shelf);
  Aabb volume;
  volume.min = Vec3(-10, 0, -10);
  volume.max = Vec3(10, 10, 10);
  setKillVolume(w, volume);
  std::vector<BodyId> removed;
  std::set<std::pair<std::uint32_t, std::uint32_t>> everIssued;
  std::size_t most = 0;
  while (w.time() < 4.0) {
    w.step();
    for (const BodyId id : spawnedBodies(w)) {
      EXPECT_TRUE(everIssued.insert({id.slot, id.generation}).second) << "an id issued twice";
    }
    for (const BodyId id : removedBodies(w)) removed.push_back(id);
    for (const RigidBody& b : w.bodies()) {
      if (!b.isStatic()) {
        EXPECT_GE(b.position().y(), -1.0) << "removed once out";
      }
    }
    most = std::max(most, w.bodies().size());
  }
  // 10 bursts of 3 from 0.5 s to 2.75 s; a ball from 5-6 m falls below 0 after about 1.05 s, so
  // the first bursts are gone before the last come.
  EXPECT_TRUE(w.isValid(shelfId));
  EXPECT_EQ(removed.size() + w.bodies().size(), 31u);
  EXPECT_GE(removed.size(), 24u);
  EXPECT_LT(most, 31u);
  for (const BodyId id : removed) EXPECT_FALSE(w.isValid(id));
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, Spawning, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return info.param > 0.01 ? "dt60" : "dt240"; });

TEST(SpawningDefs, BadDefsAreRefused) {
  World w{Settings{}};
  SpawnerDef def = ballRain();
  def.period = 0.0;
  EXPECT_THROW(addSpawner(w, def), std::invalid_argument);
  def = ballRain();
  def.regionMax.x() = -2.0;
  EXPECT_NE(checkSpawner(def).find("region"), std::string::npos);
  def = ballRain();
  def.end = def.start;
  EXPECT_NE(checkSpawner(def).find("end"), std::string::npos);
  def = ballRain();
  def.prototype.mass = -1.0;
  EXPECT_THROW(addSpawner(w, def), std::invalid_argument);
  Aabb nan;
  nan.min = Vec3(std::nan(""), 0, 0);
  EXPECT_THROW(setKillVolume(w, nan), std::invalid_argument);
}

TEST(SpawningScene, PeriodicSpawnBlocksAndTheKillVolumeAreRead) {
  using nlohmann::json;
  json doc = {{"world", {{"dt", 1.0 / 60.0}, {"duration", 3.0}}},
              {"spawn", {{{"name", "rock"}, {"count", 2}, {"period", 0.5}, {"start", 0.25}, {"seed", 7},
                          {"region", {{"min", {0, 2, 0}}, {"max", {1, 3, 1}}}},
                          {"body", {{"shape", {{"type", "sphere"}, {"radius", 0.2}}}, {"mass", 1}}}}}},
              {"kill_volume", {{"min", {-5, -1, -5}}, {"max", {5, 10, 5}}}}};
  const Scene scene = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  EXPECT_TRUE(scene.bodies.empty());
  ASSERT_EQ(scene.spawners.size(), 1u);
  EXPECT_EQ(scene.spawners[0].count, 2);
  EXPECT_EQ(scene.spawners[0].period, 0.5);
  EXPECT_EQ(scene.spawners[0].seed, 7u);
  World w = buildWorld(scene);
  for (int i = 0; i < 60; ++i) w.step();
  EXPECT_EQ(w.bodies().size(), 4u) << "bursts at 0.25 and 0.75 s";

  // A compound template with a filter spawns compound bodies (a case the first version refused).
  json hammers = doc;
  hammers["spawn"][0]["body"] = {{"mass", 1}, {"shapes", {{{"type", "capsule"}, {"radius", 0.02}, {"length", 0.3}},
                                                         {{"type", "box"}, {"extents", {0.15, 0.05, 0.05}}, {"position", {0, 0.18, 0}}, {"filter", {{"group", -1}}}}}}};
  World h = buildWorld(parseScene(hammers, "test.json", RBSIM_TEST_DATA_DIR));
  for (int i = 0; i < 30; ++i) h.step();
  ASSERT_EQ(h.bodies().size(), 2u);
  EXPECT_EQ(h.bodies()[0].children().size(), 2u);
  EXPECT_EQ(h.bodies()[0].children()[1].filter.group, -1);

  const auto field = [&](const std::function<void(json&)>& change) {
    json bad = doc;
    change(bad);
    try {
      parseScene(bad, "test.json", RBSIM_TEST_DATA_DIR);
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("no error");
  };
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["period"] = 0; }), "spawn[0].period");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["end"] = 0.1; }), "spawn[0].end");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["period"] = 1e-6; d["spawn"][0]["count"] = 100; }), "spawn[0].period");
  EXPECT_EQ(field([](json& d) { d["spawn"][0].erase("period"); d["spawn"][0]["start"] = 1; }), "spawn[0].start");
  EXPECT_EQ(field([](json& d) { d["kill_volume"]["max"] = {5, -2, 5}; }), "kill_volume.max");
}

}  // namespace
}  // namespace rbsim
