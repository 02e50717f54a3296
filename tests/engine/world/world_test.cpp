// world/world: the step pipeline's stages, pose events, scripted forces, determinism and the
// time-step guard.
#include "rbsim/world/world.h"
#include "rbsim/world/queries.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxDef;

// dt = 1/64 s is a power of two, so step start times n dt are exact and event timing is crisp.
constexpr double kWorldDt = 1.0 / 64.0;

Settings settingsWith(const Vec3& gravity, double dt = kWorldDt, Integrator integrator = Integrator::ExpMap) {
  Settings s;
  s.gravity = gravity;
  s.timeStep = dt;
  s.integrator = integrator;
  return s;
}

void stepWorld(World& world, int n) {
  for (int i = 0; i < n; ++i) world.step();
}

const StageStats& stats(const World& w, Stage s) { return w.stageStats(s); }

TEST(World, IntegrateRunsEveryStepAndForcesAreSkippedWhenNothingActs) {
  World world(settingsWith(Vec3::Zero()));
  world.addBody(boxDef(Vec3::Ones(), 1.0));
  stepWorld(world, 10);
  EXPECT_EQ(world.stepCount(), 10u);
  EXPECT_DOUBLE_EQ(world.time(), 10 * kWorldDt);
  EXPECT_EQ(stats(world, Stage::Integrate).runs, 10u);
  EXPECT_EQ(stats(world, Stage::Integrate).skipped, 0u);
  EXPECT_EQ(stats(world, Stage::AccumulateForces).runs, 0u) << "no gravity, no scripted forces";
  EXPECT_EQ(stats(world, Stage::AccumulateForces).skipped, 10u);
  EXPECT_EQ(stats(world, Stage::ApplyPoseEvents).runs, 0u);
  EXPECT_EQ(stats(world, Stage::ApplyPoseEvents).skipped, 10u);
}

TEST(World, AccumulateForcesRunsForScriptedForcesWhileIntegrateAddsGravityAlone) {
  World falling(settingsWith(Vec3(0.0, -9.81, 0.0)));
  falling.addBody(boxDef(Vec3::Ones(), 1.0));
  stepWorld(falling, 5);
  EXPECT_EQ(stats(falling, Stage::AccumulateForces).runs, 0u) << "gravity alone needs no pass of its own";
  EXPECT_DOUBLE_EQ(falling.bodies()[0].velocity().y(), -9.81 * 5 * kWorldDt) << "and still acts";

  World pushed(settingsWith(Vec3::Zero()));
  pushed.addBody(boxDef(Vec3::Ones(), 1.0));
  ScriptedForce f;
  f.body = pushed.idAt(0);
  f.force = Vec3(1.0, 0.0, 0.0);
  f.start = 0.0;
  f.end = 1.0;
  pushed.addForce(f);
  stepWorld(pushed, 5);
  EXPECT_EQ(stats(pushed, Stage::AccumulateForces).runs, 5u);
}

TEST(World, StageNamesAreDistinct) {
  EXPECT_STREQ(stageName(Stage::ApplyPoseEvents), "apply-pose-events");
  EXPECT_STREQ(stageName(Stage::AccumulateForces), "accumulate-forces");
  EXPECT_STREQ(stageName(Stage::Integrate), "integrate");
}

TEST(World, PoseEventAppliesAtTheFirstStepStartingAtOrAfterItsTime) {
  World world(settingsWith(Vec3::Zero()));
  BodyDef def = boxDef(Vec3(1.0, 2.0, 3.0), 1.0);
  def.position = Vec3(1.0, 1.0, 1.0);
  world.addBody(def);
  PoseEvent e;
  e.body = world.idAt(0);
  e.time = 0.1;  // steps start at n/64: step 6 starts at 0.09375, step 7 at 0.109375
  e.position = Vec3(5.0, 6.0, 7.0);
  e.orientation = quatFromAxisAngle(Vec3(0.0, 0.5, 0.0));
  e.velocity = Vec3(0.0, 0.0, 64.0);  // one metre per step
  world.addPoseEvent(e);
  stepWorld(world, 7);  // steps 0..6
  EXPECT_TRUE(allNear(world.bodies()[0].position(), def.position, 0.0)) << "not yet";
  EXPECT_EQ(stats(world, Stage::ApplyPoseEvents).runs, 0u);
  world.step();  // step 7: the event, then one integration with the new velocity
  const RigidBody& body = world.bodies()[0];
  EXPECT_TRUE(allNear(body.position(), Vec3(5.0, 6.0, 8.0), 0.0));
  EXPECT_LT(rotationAngleBetween(body.rotation(), e.orientation->toRotationMatrix()), 1e-15);
  for (std::size_t i = 0; i < body.vertexCount(); ++i) {
    EXPECT_TRUE(allNear(body.worldVertex(i), body.rotation() * body.bodyVertex(i) + body.position(), 1e-14));
  }
  stepWorld(world, 20);
  EXPECT_EQ(stats(world, Stage::ApplyPoseEvents).runs, 1u) << "runs only at the event's step";
  EXPECT_EQ(stats(world, Stage::ApplyPoseEvents).skipped, 27u);
  EXPECT_TRUE(allNear(world.bodies()[0].position(), Vec3(5.0, 6.0, 28.0), 1e-13));
}

TEST(World, PoseEventExactlyAtAStepStartAppliesAtThatStep) {
  World world(settingsWith(Vec3::Zero()));
  world.addBody(boxDef(Vec3::Ones(), 1.0));
  PoseEvent e;
  e.body = world.idAt(0);
  e.time = 8 * kWorldDt;
  e.angularVelocity = Vec3(0.0, 0.0, 2.0);
  world.addPoseEvent(e);
  stepWorld(world, 8);
  EXPECT_TRUE(allNear(world.bodies()[0].angularVelocity(), Vec3::Zero(), 0.0));
  world.step();
  EXPECT_TRUE(allNear(world.bodies()[0].angularVelocity(), Vec3(0.0, 0.0, 2.0), 1e-15));
  EXPECT_NEAR(rotationAngleBetween(Mat3::Identity(), world.bodies()[0].rotation()), 2.0 * kWorldDt, 1e-15)
      << "one step of expmap at the new omega";
}

TEST(World, WorldVerticesAreRpPlusXAfterSteps) {
  World world(settingsWith(Vec3(0.0, -9.81, 0.0)));
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  def.velocity = Vec3(1.0, 2.0, 0.0);
  def.angularVelocity = Vec3(0.5, 3.0, -1.0);
  world.addBody(def);
  stepWorld(world, 100);
  const RigidBody& body = world.bodies()[0];
  const Mat3 R = body.orientation().toRotationMatrix();
  for (std::size_t i = 0; i < body.vertexCount(); ++i) {
    EXPECT_TRUE(allNear(body.worldVertex(i), R * body.bodyVertex(i) + body.position(), 1e-14)) << i;
  }
}

TEST(World, ScriptedForceGivesImpulseForceTimesDuration) {
  World world(settingsWith(Vec3::Zero()));
  world.addBody(boxDef(Vec3::Ones(), 2.0));
  ScriptedForce f;
  f.body = world.idAt(0);
  f.force = Vec3(3.0, -1.5, 0.75);
  f.start = 0.0;
  f.end = 0.25;  // steps 0..15 start before 0.25: exactly 16 steps of dt = 1/64
  world.addForce(f);
  stepWorld(world, 40);
  // Dyadic values: every partial sum is exact, so the impulse is F T to the last bit.
  EXPECT_TRUE(allNear(world.bodies()[0].state().linearMomentum, 0.25 * f.force, 0.0));
  EXPECT_TRUE(allNear(world.bodies()[0].state().angularMomentum, Vec3::Zero(), 0.0))
      << "applied at the centre of mass";
  EXPECT_TRUE(activeForces(world, world.idAt(0), 0.25).empty()) << "the window is [start, end)";
  EXPECT_EQ(activeForces(world, world.idAt(0), 0.0).size(), 1u);
}

TEST(World, ScriptedForceOffCentreGivesAngularImpulse) {
  World world(settingsWith(Vec3::Zero()));
  world.addBody(boxDef(Vec3::Ones(), 1.0));
  ScriptedForce f;
  f.body = world.idAt(0);
  f.force = Vec3(0.0, 2.0, 0.0);   // world frame
  f.point = Vec3(0.5, 0.0, 0.0);   // body frame, relative to the centre of mass
  f.start = 0.0;
  f.end = 1.0 / 64.0;              // a single step, before the body has turned
  world.addForce(f);
  stepWorld(world, 3);
  EXPECT_TRUE(allNear(world.bodies()[0].state().angularMomentum, kWorldDt * Vec3(0.0, 0.0, 1.0), 0.0))
      << "L = dt (r x f) = dt (0, 0, 1)";
}

TEST(World, BodyFrameForceTurnsWithTheBody) {
  const double w = 4.0;  // about body z, a principal axis: omega stays constant
  World world(settingsWith(Vec3::Zero()));
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  def.angularVelocity = Vec3(0.0, 0.0, w);
  world.addBody(def);
  ScriptedForce f;
  f.body = world.idAt(0);
  f.force = Vec3(1.0, 0.0, 0.0);  // along body x, applied at the centre of mass: no torque
  f.forceFrame = Frame::Body;
  f.start = 0.0;
  f.end = 10.0;
  world.addForce(f);
  Vec3 expected = Vec3::Zero();
  for (int n = 0; n < 64; ++n) {
    const Mat3 Rn = rotationFromAxisAngle(Vec3(0.0, 0.0, w * n * kWorldDt));  // expmap is exact here
    const auto active = activeForces(world, world.idAt(0), world.time());
    ASSERT_EQ(active.size(), 1u);
    EXPECT_TRUE(allNear(active[0].second, Rn * f.force, 1e-13)) << "step " << n;
    expected += kWorldDt * (Rn * f.force);
    world.step();
  }
  EXPECT_TRUE(allNear(world.bodies()[0].state().linearMomentum, expected, 1e-13));
  // A world-frame force would have given P = (1, 0, 0) after 1 s; the body-frame one swept
  // round by 4 rad gives much less along x.
  EXPECT_LT(world.bodies()[0].state().linearMomentum.x(), 0.5);
}

World deterministicWorld(double velocityNudge) {
  World world(settingsWith(Vec3(0.0, -9.81, 0.0), 1.0 / 240.0, Integrator::EulerQuat));
  BodyDef a = boxDef(Vec3(1.0, 0.3, 0.1), 1.0, "a");
  a.velocity = Vec3(0.3, 4.0, -0.2 + velocityNudge);
  a.angularVelocity = Vec3(0.5, 0.3, 6.0);
  BodyDef b = boxDef(Vec3(0.5, 0.5, 2.0), 3.0, "b");
  b.position = Vec3(2.0, 0.0, 0.0);
  b.angularVelocity = Vec3(-1.0, 2.0, 0.1);
  world.addBody(a);
  world.addBody(b);
  ScriptedForce push;
  push.body = world.idAt(1);
  push.force = Vec3(0.0, 5.0, 1.0);
  push.point = Vec3(0.25, 0.0, 0.9);
  push.forceFrame = Frame::Body;
  push.start = 0.5;
  push.end = 2.0;
  world.addForce(push);
  return world;
}

TEST(World, SameSceneSameHashAndATinyChangeChangesIt) {
  World first = deterministicWorld(0.0);
  World second = deterministicWorld(0.0);
  World nudged = deterministicWorld(1e-12);
  EXPECT_EQ(first.stateHash(), second.stateHash());
  stepWorld(first, 1000);
  stepWorld(second, 1000);
  stepWorld(nudged, 1000);
  EXPECT_EQ(first.stateHash(), second.stateHash()) << "bit-identical runs";
  EXPECT_NE(first.stateHash(), nudged.stateHash()) << "1e-12 m/s in one velocity must show";
}

TEST(World, RejectsBadTimeSteps) {
  for (double dt : {0.0, -0.01, std::nan(""), std::numeric_limits<double>::infinity(), 0.1000001, 1.0}) {
    EXPECT_THROW(World{settingsWith(Vec3::Zero(), dt)}, std::invalid_argument) << "dt " << dt;
  }
  EXPECT_NO_THROW(World{settingsWith(Vec3::Zero(), kMaxTimeStep)});
  EXPECT_THROW(World{settingsWith(Vec3(0.0, std::nan(""), 0.0))}, std::invalid_argument);
}

TEST(World, ScriptsMustNameABody) {
  World world(settingsWith(Vec3::Zero()));
  world.addBody(boxDef(Vec3::Ones(), 1.0));
  ScriptedForce f;
  f.body = BodyId{1, 0};  // a slot no body has had
  EXPECT_THROW(world.addForce(f), std::invalid_argument);
  PoseEvent e;
  e.body = BodyId{3, 0};
  EXPECT_THROW(world.addPoseEvent(e), std::invalid_argument);
  const BodyId gone = world.addBody(boxDef(Vec3::Ones(), 1.0));
  world.destroyBody(gone);
  f.body = gone;  // a stale id: its slot's generation moved on
  EXPECT_THROW(world.addForce(f), std::invalid_argument);
}

// The hand-moved spring of window mode's drag: moving its anchor wakes a sleeping body and pulls
// it towards the anchor with seed 000's spring force; removed, it no longer acts.
TEST(World, AMovedSpringWakesItsBodyPullsItAndStopsWhenRemoved) {
  Settings settings;
  settings.gravity = Vec3::Zero();
  World world(settings);
  world.addBody(boxDef(Vec3(1.0, 1.0, 1.0), 2.0));
  Spring spring;
  spring.body = world.idAt(0);
  spring.anchor = Vec3::Zero();
  spring.point = Vec3(0.5, 0.0, 0.0);  // on the +x face
  spring.stiffness = 10.0;
  const SpringId index = addSpring(world, spring);
  world.body(world.idAt(0)).sleep();
  moveSpringAnchor(world, index, Vec3(1.5, 0.0, 0.0));
  EXPECT_TRUE(world.bodies()[0].awake());
  const Spring& moved = springs(world)[indexOf(world, index)];
  const auto [point, force] = forceOfSpring(moved, world.body(moved.body));
  EXPECT_TRUE(allNear(point, Vec3(0.5, 0.0, 0.0), 0.0));
  EXPECT_TRUE(allNear(force, Vec3(10.0, 0.0, 0.0), 1e-15)) << "k |d| along d, d = 1 m";
  world.step();
  EXPECT_NEAR(world.bodies()[0].velocity().x(), 10.0 / 2.0 * settings.timeStep, 1e-15) << "F / m dt";
  removeSpring(world, index);
  const double v = world.bodies()[0].velocity().x();
  world.step();
  EXPECT_EQ(world.bodies()[0].velocity().x(), v);
  EXPECT_TRUE(springs(world).empty());
  EXPECT_THROW(moveSpringAnchor(world, index, Vec3::Zero()), std::invalid_argument);  // removed: stale
}

}  // namespace
}  // namespace rbsim
