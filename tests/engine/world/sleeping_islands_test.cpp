// world/world with sleeping islands (issue 34): a sleeping island is not collided, moved or
// written by a step while something else in the world moves, and keeps its contacts and its
// warm-start impulses; a touch wakes the island whole, in the step of the touch, standing on the
// contacts it fell asleep with (Box2D v3's sleeping solver sets, solver_set.c).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "test_util.h"
#include "rbsim/world/world.h"
#include "world/collision_pipeline.h"
#include "world/world_access.h"

namespace rbsim {
namespace {

using test::boxDef;

constexpr int kStackHeight = 4;
constexpr double kBoxMass = 1.0;  // [kg]

Settings sleepySettings(double dt) {
  Settings s;
  s.timeStep = dt;
  s.gravity = Vec3(0.0, -9.81, 0.0);
  s.logQueries = true;
  s.queryLogCapacity = 4096;
  return s;
}

// A column of unit boxes on the ground plane, bodies 0 .. kStackHeight - 1, bottom first.
void addStack(World& world) {
  world.addPlane(Plane{}, Material{0.0, 0.6, 0.6});
  for (int i = 0; i < kStackHeight; ++i) {
    BodyDef def = boxDef(Vec3::Ones(), kBoxMass);
    def.shape = Shape::box(Vec3::Constant(0.5));
    def.material = Material{0.0, 0.6, 0.6};
    def.position = Vec3(0.0, 0.5 + i, 0.0);
    world.addBody(def);
  }
}

bool stackAsleep(const World& world) {
  for (int i = 0; i < kStackHeight; ++i) {
    if (world.bodies()[i].awake()) return false;
  }
  return true;
}

// Steps until the stack sleeps; fails the test if it does not within 10 s.
void settle(World& world) {
  const int limit = static_cast<int>(10.0 / world.settings().timeStep);
  for (int s = 0; s < limit && !stackAsleep(world); ++s) world.step();
  ASSERT_TRUE(stackAsleep(world)) << "the stack never fell asleep";
}

bool sameBits(const BodyState& a, const BodyState& b) {
  return std::memcmp(a.position.data(), b.position.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.orientation.coeffs().data(), b.orientation.coeffs().data(), 4 * sizeof(double)) == 0 &&
         std::memcmp(a.linearMomentum.data(), b.linearMomentum.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.angularMomentum.data(), b.angularMomentum.data(), 3 * sizeof(double)) == 0;
}

std::size_t stackContacts(const World& world) {
  return static_cast<std::size_t>(std::count_if(world.contacts().begin(), world.contacts().end(), [](const Contact& c) {
    return c.b < static_cast<std::size_t>(kStackHeight) && c.manifold.count > 0;
  }));
}

class SleepingIslands : public ::testing::TestWithParam<double> {};

TEST_P(SleepingIslands, AreNotCollidedMovedOrWrittenWhileAnotherBodyMoves) {
  World world(sleepySettings(GetParam()));
  addStack(world);
  settle(world);
  // A kinematic box far away keeps the world awake: it moves, so it never sleeps.
  BodyDef mover = boxDef(Vec3::Ones(), kBoxMass);
  mover.shape = Shape::box(Vec3::Constant(0.5));
  mover.isKinematic = true;
  mover.position = Vec3(50.0, 3.0, 0.0);
  mover.velocity = Vec3(0.0, 0.0, 1.0);
  world.addBody(mover);
  std::vector<BodyState> before;
  for (int i = 0; i < kStackHeight; ++i) before.push_back(world.bodies()[i].state());
  const std::size_t contactsBefore = stackContacts(world);
  ASSERT_EQ(contactsBefore, static_cast<std::size_t>(kStackHeight)) << "one plane contact, three box-box contacts";
  const std::uint64_t queriesBefore = WorldAccess::collision(world).queryLog().total();
  const std::uint64_t narrowRuns = world.stageStats(Stage::NarrowPhase).runs;
  const int steps = static_cast<int>(std::lround(2.0 / GetParam()));  // 2 s
  for (int s = 0; s < steps; ++s) world.step();
  EXPECT_GT(world.stageStats(Stage::NarrowPhase).runs, narrowRuns) << "the narrow phase ran for the moving body";
  // The counter: every narrow-phase query is logged, and none was asked for the sleeping stack.
  EXPECT_EQ(WorldAccess::collision(world).queryLog().total(), queriesBefore);
  EXPECT_TRUE(stackAsleep(world));
  for (int i = 0; i < kStackHeight; ++i) EXPECT_TRUE(sameBits(world.bodies()[i].state(), before[i])) << "box " << i;
  EXPECT_EQ(stackContacts(world), contactsBefore) << "the sleeping island keeps its contacts";
  EXPECT_GT(world.bodies()[kStackHeight].position().z(), 1.9);
}

TEST_P(SleepingIslands, WakeWholeInTheStepOfTheTouchAndStandOnTheirContacts) {
  World world(sleepySettings(GetParam()));
  addStack(world);
  settle(world);
  // A light box set down 1 mm above the top box, at rest: the touch must not shake the stack.
  BodyDef light = boxDef(Vec3::Ones(), 0.01 * kBoxMass);
  light.shape = Shape::box(Vec3::Constant(0.5));
  light.material = Material{0.0, 0.6, 0.6};
  light.position = Vec3(0.0, 0.5 + kStackHeight + 0.001, 0.0);
  world.addBody(light);
  int woken = -1;
  double fastest = 0.0;  // of the stack's boxes, once woken [m/s]
  for (int s = 0; s < 30; ++s) {
    world.step();
    int awake = 0;
    for (int i = 0; i < kStackHeight; ++i) awake += world.bodies()[i].awake() ? 1 : 0;
    if (awake > 0 && woken < 0) {
      woken = s;
      EXPECT_EQ(awake, kStackHeight) << "the island wakes whole, not one layer a step";
    }
    if (woken >= 0) {
      for (int i = 0; i < kStackHeight; ++i) fastest = std::max(fastest, world.bodies()[i].velocity().norm());
    }
  }
  ASSERT_GE(woken, 0) << "the touch woke nothing";
  // Woken a layer a step, each box fell a step with nothing under it: g dt = 0.16 m/s at 1/60 s.
  // Woken whole, the 10 g box's landing moves the stack far less.
  EXPECT_LT(fastest, 0.02) << "woken at step " << woken;
}

TEST_P(SleepingIslands, KeepTheirContactsWhenAnotherBodyIsDestroyed) {
  World world(sleepySettings(GetParam()));
  addStack(world);
  settle(world);
  // Two kinematic boxes far away; destroying the first moves the second into its index.
  BodyId first;
  for (int k = 0; k < 2; ++k) {
    BodyDef mover = boxDef(Vec3::Ones(), kBoxMass);
    mover.shape = Shape::box(Vec3::Constant(0.5));
    mover.isKinematic = true;
    mover.position = Vec3(50.0 + 5.0 * k, 3.0, 0.0);
    mover.velocity = Vec3(0.0, 0.0, 1.0);
    const BodyId id = world.addBody(mover);
    if (k == 0) first = id;
  }
  world.step();
  world.destroyBody(first);
  EXPECT_EQ(stackContacts(world), static_cast<std::size_t>(kStackHeight));
  const std::uint64_t queriesBefore = WorldAccess::collision(world).queryLog().total();
  for (int s = 0; s < 30; ++s) world.step();
  EXPECT_TRUE(stackAsleep(world));
  EXPECT_EQ(WorldAccess::collision(world).queryLog().total(), queriesBefore) << "the sleeping stack is still not collided";
  EXPECT_EQ(stackContacts(world), static_cast<std::size_t>(kStackHeight)) << "and still has its contacts";
}

// Issue 58: the step's contacts, which the solver and the event tracker go through, and the broad
// phase's pairs hold nothing of a sleeping island; contacts() still reports its contacts, the ones
// it fell asleep with, and a body woken by hand wakes the island whole at the next step.
TEST_P(SleepingIslands, AreKeptApartFromTheStepAndComeBackWhenTouchedByHand) {
  World world(sleepySettings(GetParam()));
  addStack(world);
  BodyDef mover = boxDef(Vec3::Ones(), kBoxMass);
  mover.shape = Shape::box(Vec3::Constant(0.5));
  mover.isKinematic = true;
  mover.position = Vec3(50.0, 3.0, 0.0);
  mover.velocity = Vec3(0.0, 0.0, 1.0);
  world.addBody(mover);
  settle(world);
  const std::vector<Contact> asleep(world.contacts().begin(), world.contacts().end());
  ASSERT_EQ(stackContacts(world), static_cast<std::size_t>(kStackHeight));
  for (int s = 0; s < 10; ++s) world.step();
  const CollisionPipeline& collision = WorldAccess::collision(world);
  for (const Contact& c : collision.contacts()) EXPECT_GE(c.b, static_cast<std::size_t>(kStackHeight)) << "a sleeping contact in the step's";
  for (const ProxyPair& p : collision.candidatePairs()) {
    EXPECT_TRUE(world.bodies()[collision.bodyOfProxy(p.a)].awake() || world.bodies()[collision.bodyOfProxy(p.b)].awake());
  }
  ASSERT_EQ(world.contacts().size(), asleep.size());
  for (std::size_t k = 0; k < asleep.size(); ++k) {
    const Contact& now = world.contacts()[k];
    EXPECT_TRUE(now.a == asleep[k].a && now.b == asleep[k].b && now.manifold.count == asleep[k].manifold.count &&
                std::memcmp(now.manifold.points.data(), asleep[k].manifold.points.data(), sizeof(now.manifold.points)) == 0)
        << "contact " << k << " is the one it fell asleep with";
  }
  world.body(world.idAt(kStackHeight - 1)).wake();  // the top box, by hand
  world.step();
  for (int i = 0; i < kStackHeight; ++i) {
    EXPECT_TRUE(world.bodies()[i].awake()) << "box " << i << " wakes with its island";
    EXPECT_LT(world.bodies()[i].velocity().norm(), 0.02) << "and stands on its contacts";
  }
  EXPECT_EQ(stackContacts(world), static_cast<std::size_t>(kStackHeight));
}

// Issue 58: an island's contacts go aside in the step it falls asleep (Box2D v3's
// b2TrySleepIsland), not at the next narrow phase, which never comes while nothing is awake: the
// step's contacts and the broad phase's awake proxies then hold nothing of it, so that a removal
// visits only what it touches. contacts() reports, bit for bit, the contacts that step found (the
// same step with sleep off finds them: sleep comes after), and the solved points leave with them,
// as a sleeping pair's are never reported.
TEST_P(SleepingIslands, GoAsideInTheStepTheyFallAsleep) {
  World world(sleepySettings(GetParam()));
  addStack(world);
  World before = world;
  const int limit = static_cast<int>(10.0 / world.settings().timeStep);
  for (int s = 0; s < limit && !stackAsleep(world); ++s) {
    before = world;
    world.step();
  }
  ASSERT_TRUE(stackAsleep(world)) << "the stack never fell asleep";
  Settings noSleep = before.settings();
  noSleep.allowSleep = false;
  before.setSettings(noSleep);
  before.step();
  const CollisionPipeline& collision = WorldAccess::collision(world);
  EXPECT_TRUE(collision.contacts().empty()) << "the step's contacts hold the sleeping island's";
  EXPECT_TRUE(collision.broadPhaseAwake().empty()) << "the broad phase holds a sleeping proxy as awake";
  EXPECT_TRUE(world.contactPoints().empty());
  EXPECT_EQ(before.contactPoints().size(), static_cast<std::size_t>(4 * kStackHeight)) << "each box stands on a face";
  std::vector<Contact> found(before.contacts().begin(), before.contacts().end());
  std::sort(found.begin(), found.end(), keptBefore);
  ASSERT_EQ(world.contacts().size(), found.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    const Contact& now = world.contacts()[k];
    EXPECT_TRUE(now.kind == found[k].kind && now.a == found[k].a && now.b == found[k].b &&
                now.manifold.count == found[k].manifold.count &&
                std::memcmp(now.manifold.points.data(), found[k].manifold.points.data(), sizeof(now.manifold.points)) == 0)
        << "contact " << k << " is the one the step found";
  }
  // Removing the top box wakes the one it stood on, whose island wakes whole at the next step and
  // stands on the contacts it fell asleep with.
  world.destroyBody(world.idAt(kStackHeight - 1));
  EXPECT_TRUE(world.bodies()[kStackHeight - 2].awake());
  EXPECT_FALSE(world.bodies()[0].awake()) << "the rest of the island wakes at the next step, not in the removal";
  world.step();
  for (int i = 0; i + 1 < kStackHeight; ++i) {
    EXPECT_TRUE(world.bodies()[i].awake()) << "box " << i << " wakes with its island";
    EXPECT_LT(world.bodies()[i].velocity().norm(), 0.02) << "and stands on its contacts";
  }
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, SleepingIslands, ::testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return "dt_1_over_" + std::to_string(static_cast<int>(std::lround(1.0 / info.param)));
                         });

}  // namespace
}  // namespace rbsim
