// world/world: sleeping bodies (Settings::allowSleep, sleepLinearSpeed, sleepAngularSpeed,
// timeToSleep) and stage skipping (Settings::skipIdleStages). A body slow for timeToSleep stops
// being integrated, with zero momenta; forces and pose events wake it. Skipping stages must
// never change a result.
#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/world/world.h"
#include "rbsim/world/queries.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxDef;

// dt = 1/64 s is a power of two: the resting time k dt is exact, so the step a body falls
// asleep at is exactly timeToSleep / dt = 32.
constexpr double kSleepDt = 1.0 / 64.0;
constexpr int kStepsToSleep = 32;

Settings zeroGravity() {
  Settings s;
  s.gravity = Vec3::Zero();
  s.timeStep = kSleepDt;
  return s;
}

World worldWithBox(const Settings& settings, const Vec3& velocity, const Vec3& angularVelocity = Vec3::Zero()) {
  World world(settings);
  BodyDef def = boxDef(Vec3(1.0, 0.5, 0.25), 2.0);
  def.position = Vec3(1.0, 2.0, 3.0);
  def.velocity = velocity;
  def.angularVelocity = angularVelocity;
  world.addBody(def);
  return world;
}

void stepSleep(World& world, int n) {
  for (int i = 0; i < n; ++i) world.step();
}

TEST(Sleep, ABodyAtRestSleepsAfterTimeToSleepAndIsNoLongerIntegrated) {
  World world = worldWithBox(zeroGravity(), Vec3::Zero());
  stepSleep(world, kStepsToSleep - 1);
  EXPECT_TRUE(world.bodies()[0].awake()) << "one step short of timeToSleep";
  world.step();
  EXPECT_FALSE(world.bodies()[0].awake());
  EXPECT_EQ(awakeCount(world), 0u);
  const std::uint64_t integrated = world.stageStats(Stage::Integrate).runs;
  stepSleep(world, 100);
  EXPECT_EQ(world.stageStats(Stage::Integrate).runs, integrated) << "nothing awake: Integrate is skipped";
  EXPECT_EQ(world.stageStats(Stage::UpdateSleep).skipped, 100u);
  EXPECT_TRUE(allNear(world.bodies()[0].position(), Vec3(1.0, 2.0, 3.0), 0.0));
}

TEST(Sleep, ASlowDriftStopsWithZeroMomenta) {
  // 5 mm/s and 0.02 rad/s are below the default 10 mm/s and 0.035 rad/s: the body sleeps at
  // step 32 having drifted 32 dt v, and then reads back at rest.
  const Vec3 v(0.005, 0.0, 0.0), w(0.0, 0.02, 0.0);
  World world = worldWithBox(zeroGravity(), v, w);
  stepSleep(world, kStepsToSleep + 10);
  const RigidBody& body = world.bodies()[0];
  ASSERT_FALSE(body.awake());
  EXPECT_TRUE(allNear(body.position(), Vec3(1.0, 2.0, 3.0) + kStepsToSleep * kSleepDt * v, 1e-14));
  EXPECT_EQ(body.velocity(), Vec3::Zero());
  EXPECT_EQ(body.angularVelocity(), Vec3::Zero());
  EXPECT_EQ(body.kineticEnergy(), 0.0);
}

TEST(Sleep, EitherSpeedAboveItsThresholdKeepsTheBodyAwake) {
  World fast = worldWithBox(zeroGravity(), Vec3(0.011, 0.0, 0.0));
  World spinning = worldWithBox(zeroGravity(), Vec3::Zero(), Vec3(0.0, 0.0, 0.036));
  stepSleep(fast, 10 * kStepsToSleep);
  stepSleep(spinning, 10 * kStepsToSleep);
  EXPECT_TRUE(fast.bodies()[0].awake());
  EXPECT_TRUE(spinning.bodies()[0].awake());
}

TEST(Sleep, AFreeBodyUnderGravityNeverSleepsEvenFromRest) {
  Settings s = zeroGravity();
  s.gravity = Vec3(0.0, -9.81, 0.0);
  World world = worldWithBox(s, Vec3::Zero());
  stepSleep(world, 10 * kStepsToSleep);
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_LT(world.bodies()[0].velocity().y(), -9.0) << "it has been falling for 5 s";
}

TEST(Sleep, AScriptedForceWakesTheBodyAndActsInFull) {
  // Asleep from t = 0.5 s; a 4 N push for 1 s starting at t = 1 s must give v = F t / m = 2 m/s.
  World world = worldWithBox(zeroGravity(), Vec3::Zero());
  world.addForce({world.idAt(0), Vec3(4.0, 0.0, 0.0), Vec3::Zero(), Frame::World, Frame::Body, 1.0, 2.0});
  stepSleep(world, 64);  // to t = 1 s
  ASSERT_FALSE(world.bodies()[0].awake());
  stepSleep(world, 64);  // t = 1 .. 2 s
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_TRUE(allNear(world.bodies()[0].velocity(), Vec3(2.0, 0.0, 0.0), 1e-14));
}

TEST(Sleep, APoseEventWakesTheBody) {
  World world = worldWithBox(zeroGravity(), Vec3::Zero());
  PoseEvent kick;
  kick.body = world.idAt(0);
  kick.time = 1.0;
  kick.velocity = Vec3(0.0, 0.0, 1.0);
  world.addPoseEvent(kick);
  stepSleep(world, 64);
  ASSERT_FALSE(world.bodies()[0].awake());
  stepSleep(world, 64);
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_TRUE(allNear(world.bodies()[0].position(), Vec3(1.0, 2.0, 4.0), 1e-14)) << "1 s at 1 m/s along z";
}

TEST(Sleep, DisallowedSleepKeepsEveryBodyAwakeAndSkipsTheStage) {
  Settings s = zeroGravity();
  s.allowSleep = false;
  World world = worldWithBox(s, Vec3::Zero());
  stepSleep(world, 10 * kStepsToSleep);
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_EQ(world.stageStats(Stage::UpdateSleep).runs, 0u);
  EXPECT_EQ(world.stageStats(Stage::Integrate).runs, 10u * kStepsToSleep);
}

TEST(Sleep, RunningEveryStageDoesNotSleepWhenSleepIsDisallowed) {
  // skipIdleStages = false runs UpdateSleep every step; with allowSleep = false it must still
  // leave a slow (5 mm/s) body awake and drifting.
  Settings s = zeroGravity();
  s.allowSleep = false;
  s.skipIdleStages = false;
  World world = worldWithBox(s, Vec3(0.005, 0.0, 0.0));
  stepSleep(world, 10 * kStepsToSleep);
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_TRUE(allNear(world.bodies()[0].velocity(), Vec3(0.005, 0.0, 0.0), 1e-15));
}

TEST(Settings, SleepThresholdsAreChecked) {
  for (auto bad : {+[](Settings& s) { s.sleepLinearSpeed = -1.0; }, +[](Settings& s) { s.sleepAngularSpeed = std::nan(""); },
                   +[](Settings& s) { s.timeToSleep = 0.0; }}) {
    Settings s;
    bad(s);
    EXPECT_TRUE(static_cast<bool>(checkSettings(s)));
    EXPECT_THROW(World{s}, std::invalid_argument);
  }
  EXPECT_FALSE(static_cast<bool>(checkSettings(Settings{})));
}

// A scene that exercises every stage at some point: a pose event, a push, gravity off, two
// bodies of which one rests and falls asleep.
World everyStageScene(bool skip) {
  Settings s = zeroGravity();
  s.skipIdleStages = skip;
  World world(s);
  BodyDef spinning = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  spinning.angularVelocity = Vec3(0.1, 3.0, 0.2);
  world.addBody(spinning);
  BodyDef resting = boxDef(Vec3::Ones(), 5.0, "resting");
  resting.position = Vec3(3.0, 0.0, 0.0);
  world.addBody(resting);
  world.addForce({world.idAt(0), Vec3(0.0, 1.0, 0.0), Vec3(0.5, 0.0, 0.0), Frame::Body, Frame::Body, 0.25, 0.5});
  PoseEvent nudge;
  nudge.body = world.idAt(1);
  nudge.time = 2.0;
  nudge.velocity = Vec3(0.0, 0.1, 0.0);
  world.addPoseEvent(nudge);
  return world;
}

TEST(StageSkipping, RunningIdleStagesChangesNoBitOfTheResult) {
  World skipping = everyStageScene(true);
  World running = everyStageScene(false);
  stepSleep(skipping, 256);
  stepSleep(running, 256);
  EXPECT_EQ(skipping.stateHash(), running.stateHash());
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) {
    const Stage stage = static_cast<Stage>(s);
    EXPECT_EQ(running.stageStats(stage).skipped, 0u) << stageName(stage);
    EXPECT_EQ(running.stageStats(stage).runs, 256u) << stageName(stage);
  }
  // Pose events and forces are idle at most steps; a body spins throughout, so Integrate and
  // UpdateSleep always run.
  EXPECT_EQ(skipping.stageStats(Stage::ApplyPoseEvents).runs, 1u);
  EXPECT_EQ(skipping.stageStats(Stage::AccumulateForces).runs, 16u) << "0.25 s of push at 64 steps/s";
  EXPECT_EQ(skipping.stageStats(Stage::Integrate).skipped, 0u);
}

}  // namespace
}  // namespace rbsim
