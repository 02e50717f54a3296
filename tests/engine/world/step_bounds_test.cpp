// What a budgeted input may imply for one step (issue 56, item 2): bodies piled into one place are
// refused before their pairs are listed, leaving the World as it was; a spawner's period is held
// to the time step; keyframes are found by bisection and bounded in number.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/io/input_error.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/kinematic_motion.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

// The fewest boxes at one point whose pairs, n (n - 1) / 2, pass kMaxBroadPhasePairs.
std::size_t fewestPastThePairLimit() {
  std::size_t n = 2;
  while (n * (n - 1) / 2 <= kMaxBroadPhasePairs) ++n;
  return n;
}

BodyId pileBox(World& w, int k) {
  BodyDef def = shapeBodyDef(Shape::box(Vec3::Constant(0.5)), 1.0, "pile_" + std::to_string(k));
  return w.addBody(def);  // all at the origin
}

TEST(StepBounds, BodiesPiledAtOnePointAreRefusedAndTheWorldIsLeftAsItWas) {
  World w{Settings{}};  // soft step: it collides first, so nothing has moved when the pairs are counted
  std::vector<BodyId> ids;
  for (std::size_t k = 0; k < fewestPastThePairLimit(); ++k) ids.push_back(pileBox(w, static_cast<int>(k)));
  const std::uint64_t hash = w.stateHash();
  try {
    w.step();
    FAIL() << "a step over the pair limit ran";
  } catch (const StepLimitError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("step 0 (t = 0 s)"), std::string::npos) << message;
    EXPECT_NE(message.find(std::to_string(kMaxBroadPhasePairs) + " pairs"), std::string::npos) << message;
    EXPECT_NE(message.find("expected them spread out"), std::string::npos) << message;
  }
  EXPECT_EQ(w.stepCount(), 0u);
  EXPECT_EQ(w.stateHash(), hash);
  EXPECT_TRUE(w.contacts().empty());
  // Refused again while piled; once most are gone the rest step, and their pairs are found afresh.
  EXPECT_THROW(w.step(), StepLimitError);
  w.destroyBodies(std::vector<BodyId>(ids.begin() + 3, ids.end()));
  w.step();
  EXPECT_EQ(w.stepCount(), 1u);
  EXPECT_EQ(w.contacts().size(), 3u) << "three boxes at one point: three pairs, each touching";
}

SpawnerDef quickRain(double period) {
  SpawnerDef def;
  def.name = "drip";
  def.prototype = shapeBodyDef(Shape::sphere(0.1), 1.0);
  def.period = period;
  def.end = 1.0;
  return def;
}

TEST(StepBounds, ASpawnerPeriodShorterThanTheStepIsRefused) {
  Settings s;
  s.timeStep = 1.0 / 60.0;
  World w(s);
  try {
    addSpawner(w, quickRain(1e-9));
    FAIL() << "period 1e-9 s was taken";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("spawner 'drip': period: 1e-09 s is shorter than the time step"), std::string::npos) << message;
    EXPECT_NE(message.find("16666667 bursts in one step"), std::string::npos) << message;
  }
  EXPECT_THROW(addSpawner(w, quickRain(0.5 * s.timeStep)), std::invalid_argument);
  EXPECT_TRUE(spawners(w).empty());
  addSpawner(w, quickRain(s.timeStep));
  addSpawner(w, quickRain(0.016666666667 - 1e-12));  // 1/60 s to ten digits, rounded down
  EXPECT_EQ(spawners(w).size(), 2u);
  // The time step cannot grow past a spawner's period either.
  Settings longer = s;
  longer.timeStep = 0.05;
  EXPECT_THROW(w.setSettings(longer), std::invalid_argument);
  EXPECT_EQ(w.settings().timeStep, s.timeStep);
  // A burst a step: 60 steps of a 1/60 s period add 60 bodies.
  World one(s);
  addSpawner(one, quickRain(s.timeStep));
  for (int i = 0; i < 60; ++i) one.step();
  EXPECT_EQ(one.bodies().size(), 60u);
}

TEST(StepBounds, ASceneSpawnBlockWithAShortPeriodNamesItsField) {
  const std::string text = R"({"world": {"dt": 0.01, "duration": 1},
    "spawn": [{"count": 1, "period": 1e-9, "region": {"min": [0, 1, 0], "max": [0, 1, 0]},
               "body": {"shape": {"type": "sphere", "radius": 0.1}, "mass": 1}}]})";
  try {
    parseSceneText(text, "rain.json", ".");
    FAIL() << "the scene was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "rain.json");
    EXPECT_EQ(e.field(), "spawn[0].period");
    EXPECT_NE(std::string(e.what()).find("shorter than the time step, 0.01 s"), std::string::npos) << e.what();
  }
}

// The linear scan keyframePoseAt used to make: the first key after the first at or after t.
Keyframe scannedPoseAt(const KinematicMotion& motion, double t) {
  const std::vector<Keyframe>& keys = motion.keys;
  if (t <= keys.front().time) return keys.front();
  if (t >= keys.back().time) return keys.back();
  std::size_t k = 1;
  while (keys[k].time < t) ++k;
  const double s = (t - keys[k - 1].time) / (keys[k].time - keys[k - 1].time);
  return {t, keys[k - 1].position + s * (keys[k].position - keys[k - 1].position),
          keys[k - 1].orientation.slerp(s, keys[k].orientation)};
}

TEST(StepBounds, KeyframesFoundByBisectionGiveTheScannedPoses) {
  UniformRandom random(5);
  KinematicMotion motion;
  motion.kind = KinematicMotion::Kind::Keyframes;
  double time = 0.0;
  for (int k = 0; k < 1000; ++k) {
    time += random.between(0.001, 0.1);
    motion.keys.push_back({time, 10.0 * random.direction(), random.rotation()});
  }
  ASSERT_TRUE(checkKinematicMotion(motion).empty());
  std::vector<double> times{0.0, motion.keys.front().time, motion.keys.back().time, time + 1.0};
  for (const Keyframe& key : motion.keys) times.push_back(key.time);  // exactly on a key
  for (int i = 0; i < 2000; ++i) times.push_back(random.between(0.0, time));
  for (const double t : times) {
    const Keyframe found = keyframePoseAt(motion, t), scanned = scannedPoseAt(motion, t);
    EXPECT_EQ(found.position, scanned.position) << t;
    EXPECT_EQ(found.orientation.coeffs(), scanned.orientation.coeffs()) << t;
  }
}

TEST(StepBounds, KeyframesAreBoundedInNumber) {
  KinematicMotion motion;
  motion.kind = KinematicMotion::Kind::Keyframes;
  for (std::size_t k = 0; k < kMaxKeyframes; ++k) motion.keys.push_back({static_cast<double>(k), Vec3::Zero(), Quat::Identity()});
  EXPECT_TRUE(checkKinematicMotion(motion).empty());
  motion.keys.push_back({static_cast<double>(kMaxKeyframes), Vec3::Zero(), Quat::Identity()});
  EXPECT_EQ(checkKinematicMotion(motion), "keys: " + std::to_string(kMaxKeyframes + 1) + " keyframes; expected at most " +
                                              std::to_string(kMaxKeyframes) + " (a key every step of 1/60 s for 27 minutes)");
  // In a scene, refused at load under the motion's field.
  std::string keys;
  for (std::size_t k = 0; k <= kMaxKeyframes; ++k) keys += (k ? ",{\"time\":" : "{\"time\":") + std::to_string(k) + "}";
  const std::string text = R"({"bodies": [{"name": "lift", "kinematic": true, "mass": 1,
    "shape": {"type": "box", "extents": [1, 0.1, 1]}, "motion": {"keyframes": [)" + keys + "]}}]}";
  try {
    parseSceneText(text, "lift.json", ".");
    FAIL() << "the scene was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "bodies[0].motion.keyframes");
    EXPECT_NE(std::string(e.what()).find("expected at most " + std::to_string(kMaxKeyframes)), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbsim
