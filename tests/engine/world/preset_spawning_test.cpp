// Spawners of presets (world/spawner.h): ragdolls in bursts, several copies at fixed offsets from
// each drawn point, and bursts removed at an age with their joints (Box3D's rain benchmark); the
// scene's "ragdoll", "offsets" and "lifetime" keys, and the rain scene's schedule.
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

constexpr double kSpawnG = 9.81;  // [m/s^2], Settings' default gravity

// Two figures 1.5 m apart, 5 m up, dropped every 0.5 s and cleared 0.75 s after they came.
SpawnerDef figureRain() {
  SpawnerDef def;
  def.name = "doll";
  def.ragdoll = RagdollDef{};
  def.offsets = {Vec3(-0.75, 0, 0), Vec3(0.75, 0, 0)};
  def.regionMin = Vec3(-1, 5, -1);
  def.regionMax = Vec3(1, 5, 1);
  def.speedMin = 0.5;
  def.speedMax = 1.0;
  def.randomOrientation = false;
  def.period = 0.5;
  def.lifetime = 0.75;
  return def;
}

class PresetSpawning : public testing::TestWithParam<double> {
 protected:
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam();
    return s;
  }
};

// Bursts at 0, 0.5, 1.0, 1.5 s each add two figures (22 bodies, 20 joints); each burst goes 0.75 s
// after it came, joints with it: 22 bodies from 0, 44 from 0.5, 22 from 0.75, 44 from 1.0, ...
// Removed ids are exactly a burst's, never issued again, and every joint joins two bones of one figure.
TEST_P(PresetSpawning, BurstsOfRagdollsComeAndGoWithTheirJoints) {
  World w(settings());
  addSpawner(w, figureRain());
  std::set<std::pair<std::uint32_t, std::uint32_t>> issued;
  std::map<double, std::vector<BodyId>> bursts;  // by the time they came
  while (w.time() < 2.0) {
    const double t = w.time();
    w.step();
    for (const BodyId id : spawnedBodies(w)) EXPECT_TRUE(issued.insert({id.slot, id.generation}).second) << "an id issued twice";
    if (!spawnedBodies(w).empty()) {
      EXPECT_EQ(spawnedBodies(w).size(), 2 * kBoneCount) << "at " << t;
      bursts[t] = spawnedBodies(w);
    }
    if (!removedBodies(w).empty()) {
      // The burst 0.75 s older, to the half step the schedule rounds to.
      const auto oldest = bursts.begin();
      ASSERT_NE(oldest, bursts.end());
      EXPECT_NEAR(t - oldest->first, 0.75, 0.5 * GetParam());
      EXPECT_EQ(removedBodies(w), oldest->second);
      for (const BodyId id : oldest->second) EXPECT_FALSE(w.isValid(id));
      bursts.erase(oldest);
    }
    // Bursts and removals fall due at the step whose start is within half a step of their time.
    const double due = t + 0.5 * GetParam();
    const std::size_t figures = due < 0.5 || std::fmod(due, 0.5) >= 0.25 ? 2 : 4;
    EXPECT_EQ(w.bodies().size(), figures * kBoneCount) << "at " << t;
    EXPECT_EQ(w.joints().size(), figures * (kBoneCount - 1)) << "at " << t;
    for (const Joint& j : w.joints()) {
      const std::string& a = w.bodies()[w.indexOf(j.def.bodyA)].name();
      const std::string& b = w.bodies()[w.indexOf(j.def.bodyB)].name();
      EXPECT_EQ(a.substr(0, a.find('_', 5)), b.substr(0, b.find('_', 5))) << a << " joined to " << b;
    }
  }
  EXPECT_EQ(spawners(w)[0].bursts, 4u);
}

// Two figures spawned overlapping (0.2 m apart) push each other apart as they fall, their joints
// pull their bones back together; every one of those impulses is equal and opposite, so the pair's
// momentum is 2 M (v0 + g t) to rounding, while each figure's alone is not.
TEST_P(PresetSpawning, FallingFiguresKeepTheirMomentumLaw) {
  World w(settings());
  SpawnerDef def = figureRain();
  def.offsets = {Vec3(-0.1, 0, 0), Vec3(0.1, 0, 0)};
  def.lifetime = std::numeric_limits<double>::infinity();
  def.end = 0.1;  // one burst
  addSpawner(w, def);
  const auto momentum = [&](std::size_t first, std::size_t bones) {
    Vec3 p = Vec3::Zero();
    double m = 0.0;
    for (std::size_t i = first; i < first + bones; ++i) {
      p += w.bodies()[i].state().linearMomentum;
      m += w.bodies()[i].mass();
    }
    return std::make_pair(p, m);
  };
  w.step();
  ASSERT_EQ(w.bodies().size(), 2 * kBoneCount);
  EXPECT_NEAR((w.bodies()[11].position() - w.bodies()[0].position()).x(), 0.2, 0.05) << "the offsets, pushed apart a little";
  // v0 as drawn (|v0| in the speed range) from the first step's momentum, less its gravity.
  const auto [p1, m1] = momentum(0, 2 * kBoneCount);
  const Vec3 v0 = p1 / m1 - Vec3(0, -kSpawnG, 0) * w.time();
  EXPECT_GE(v0.norm(), 0.5 - 1e-9);
  EXPECT_LE(v0.norm(), 1.0 + 1e-9);
  while (w.time() < 0.8) w.step();  // about 3 m of fall: still in the air
  const auto [p, m] = momentum(0, 2 * kBoneCount);
  EXPECT_NEAR(m, 2.0 * RagdollDef{}.mass, 1e-9);
  const Vec3 expected = m * (v0 + Vec3(0, -kSpawnG, 0) * w.time());
  EXPECT_LT((p - expected).norm(), 1e-9 * m * kSpawnG * w.time()) << p.transpose() << " vs " << expected.transpose();
  const auto [pLeft, mLeft] = momentum(0, kBoneCount);
  const double pushed = (pLeft - mLeft * (v0 + Vec3(0, -kSpawnG, 0) * w.time())).norm();
  EXPECT_GT(pushed, 0.5) << "the figures pushed each other [kg m/s]";
}

// A body spawner's copies sit at their offsets from the drawn point (x and z untouched by gravity
// in one step from rest), named in order; a burst the kill volume took first is not removed twice.
TEST_P(PresetSpawning, OffsetsPlaceCopiesAndTheKillVolumeMayTakeThemFirst) {
  World w(settings());
  SpawnerDef def;
  def.name = "row";
  def.prototype = shapeBodyDef(Shape::sphere(0.1), 1.0);
  def.count = 2;
  def.offsets = {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1.0, 0, 0)};
  def.regionMin = Vec3(-2, 3, -2);
  def.regionMax = Vec3(2, 3, 2);
  def.randomOrientation = false;
  def.period = 0.4;
  def.lifetime = 1.0;
  addSpawner(w, def);
  Aabb volume;
  volume.min = Vec3(-10, 1, -10);  // a ball from 3 m leaves it after 0.64 s, before its lifetime
  volume.max = Vec3(10, 10, 10);
  w.step();
  ASSERT_EQ(w.bodies().size(), 6u);
  for (std::size_t point = 0; point < 2; ++point) {
    for (std::size_t k = 0; k < 3; ++k) {
      const RigidBody& b = w.bodies()[3 * point + k];
      EXPECT_EQ(b.name(), "row_" + std::to_string(3 * point + k));
      EXPECT_EQ(b.position().x(), w.bodies()[3 * point].position().x() + 0.5 * static_cast<double>(k));
      EXPECT_EQ(b.position().z(), w.bodies()[3 * point].position().z());
    }
  }
  setKillVolume(w, volume);
  std::size_t removed = 0;
  while (w.time() < 3.0) {
    w.step();
    removed += removedBodies(w).size();
    for (const BodyId id : removedBodies(w)) EXPECT_FALSE(w.isValid(id));
  }
  // Bursts at 0, 0.4, ..., 2.8 s (8 of 6 balls); those of 2.4 and 2.8 s are still up at 3.0 s.
  EXPECT_EQ(removed + w.bodies().size(), 48u);
  EXPECT_EQ(w.bodies().size(), 12u);
}

// A copy of the World mid-run carries the bursts still alive and their removal times with it.
TEST_P(PresetSpawning, ACopyRemovesWhatTheOriginalRemoves) {
  World w(settings());
  addSpawner(w, figureRain());
  while (w.time() < 0.6) w.step();
  World copy(w);
  for (int i = 0; i < static_cast<int>(0.5 / GetParam()); ++i) {
    w.step();
    copy.step();
    EXPECT_EQ(w.bodies().size(), copy.bodies().size());
  }
  EXPECT_EQ(w.stateHash(), copy.stateHash());
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, PresetSpawning, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return info.param > 0.01 ? "dt60" : "dt240"; });

TEST(PresetSpawningDefs, BadDefsAreRefused) {
  SpawnerDef def = figureRain();
  EXPECT_TRUE(checkSpawner(def).empty()) << checkSpawner(def);
  def.offsets.clear();
  EXPECT_NE(checkSpawner(def).find("offsets"), std::string::npos);
  def = figureRain();
  def.offsets[1].y() = std::nan("");
  EXPECT_NE(checkSpawner(def).find("offsets"), std::string::npos);
  def = figureRain();
  def.lifetime = 0.0;
  EXPECT_NE(checkSpawner(def).find("lifetime"), std::string::npos);
  def = figureRain();
  def.spinMax = 1.0;
  EXPECT_NE(checkSpawner(def).find("angular_speed"), std::string::npos);
  def = figureRain();
  def.ragdoll->mass = -70.0;
  World soft{Settings{}};
  EXPECT_THROW(addSpawner(soft, def), std::invalid_argument) << "the figure's checks, before its first burst";
  EXPECT_TRUE(spawners(soft).empty());
  Settings pgs;
  pgs.solver = Settings::ContactSolverMethod::Pgs;
  World w(pgs);
  EXPECT_THROW(addSpawner(w, figureRain()), std::invalid_argument) << "a ragdoll needs the soft step";
}

nlohmann::json ragdollSpawnScene() {
  return {{"world", {{"dt", 1.0 / 60.0}, {"duration", 2.0}}},
          {"spawn", {{{"name", "fig"}, {"period", 0.5}, {"lifetime", 0.75}, {"random_orientation", false},
                      {"offsets", {{0, 0, 0}, {1, 0, 0}}}, {"region", {{"min", {0, 4, 0}}, {"max", {0, 4, 0}}}},
                      {"ragdoll", {{"mass", 60}, {"joint_friction", 5}, {"joint_hertz", 1}, {"joint_damping_ratio", 0.7}}}}}}};
}

TEST(PresetSpawningScene, RagdollOffsetsAndLifetimeAreRead) {
  using nlohmann::json;
  const json doc = ragdollSpawnScene();
  const Scene scene = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  ASSERT_EQ(scene.spawners.size(), 1u);
  const SpawnerDef& def = scene.spawners[0];
  ASSERT_TRUE(def.ragdoll.has_value());
  EXPECT_EQ(def.ragdoll->mass, 60.0);
  EXPECT_EQ(def.ragdoll->jointFriction, 5.0);
  EXPECT_EQ(def.ragdoll->jointDampingRatio, 0.7);
  EXPECT_EQ(def.offsets.size(), 2u);
  EXPECT_EQ(def.lifetime, 0.75);
  World w = buildWorld(scene);
  for (int i = 0; i < 40; ++i) w.step();  // t = 0.67 s: the second burst is in, the first not yet gone
  EXPECT_EQ(w.bodies().size(), 4 * kBoneCount);
  EXPECT_EQ(w.bodies()[0].name(), "fig_0_pelvis");

  // Without a period the block adds its figures at load, as the scene's "ragdolls" would.
  json once = doc;
  once["spawn"][0].erase("period");
  once["spawn"][0].erase("lifetime");
  once["spawn"][0]["count"] = 3;
  const Scene atLoad = parseScene(once, "test.json", RBSIM_TEST_DATA_DIR);
  EXPECT_TRUE(atLoad.spawners.empty());
  ASSERT_EQ(atLoad.ragdolls.size(), 6u);
  EXPECT_EQ(atLoad.ragdolls[5].name, "fig_5");
  EXPECT_EQ(atLoad.ragdolls[1].position, Vec3(1, 4, 0));

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
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["body"] = {{"shape", {{"type", "sphere"}, {"radius", 0.2}}}, {"mass", 1}}; }),
            "spawn[0].body");
  EXPECT_EQ(field([](json& d) { d["spawn"][0].erase("ragdoll"); }), "spawn[0].body");
  EXPECT_EQ(field([](json& d) { d["spawn"][0].erase("period"); }), "spawn[0].lifetime");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["lifetime"] = -1; }), "spawn[0].lifetime");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["offsets"] = json::array(); }), "spawn[0].offsets");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["offsets"] = {{0, 0}}; }), "spawn[0].offsets");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["offsets"] = {{0, 1e300, 0}}; }), "spawn[0].offsets");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["angular_speed"] = {0, 1}; }), "spawn[0].angular_speed");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["ragdoll"]["scale"] = 100; }), "spawn[0].ragdoll.scale");
  EXPECT_EQ(field([](json& d) { d["spawn"][0]["ragdoll"]["name"] = "x"; }), "spawn[0].ragdoll.name");
  EXPECT_EQ(field([](json& d) { d["world"]["solver"] = "pgs"; }), "spawn[0].ragdoll");
  // 4 points x 3000 offsets x 11 bones a burst: over the 100000-body limit.
  EXPECT_EQ(field([](json& d) {
              d["spawn"][0]["count"] = 4;
              d["spawn"][0]["offsets"] = json::array();
              for (int i = 0; i < 3000; ++i) d["spawn"][0]["offsets"].push_back({0, 0, i});
            }),
            "spawn[0].offsets");
}

// The rain scene (assets/scenes/box3d/rain.json) drops column c at Box3D's steps: the c-th step
// index k with (k & 0x2F) == 0 (benchmarks.c StepRain), and again 320 steps later, when the
// column before is cleared.
TEST(PresetSpawningScene, TheRainSceneKeepsBox3dsSchedule) {
  const Scene scene = loadScene(std::string(RBSIM_ASSET_DIR) + "/scenes/box3d/rain.json");
  std::vector<int> box3dSteps;
  for (int k = 0; box3dSteps.size() < 10; ++k) {
    if ((k & 0x2F) == 0) box3dSteps.push_back(k);
  }
  ASSERT_EQ(scene.spawners.size(), 10u);
  for (std::size_t c = 0; c < 10; ++c) {
    const SpawnerDef& s = scene.spawners[c];
    EXPECT_NEAR(s.start / scene.settings.timeStep, box3dSteps[c], 1e-9);
    EXPECT_NEAR(s.period / scene.settings.timeStep, 320.0, 1e-9);
    EXPECT_NEAR(s.lifetime / scene.settings.timeStep, 320.0, 1e-9);
    EXPECT_EQ(s.offsets.size(), 30u) << "ten groups of three";
    ASSERT_TRUE(s.ragdoll.has_value());
  }
  EXPECT_EQ(scene.bodies.size(), 100u);
}

}  // namespace
}  // namespace rbsim
