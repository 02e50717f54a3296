// world/collision_pipeline and world/continuous_collision: the collision stages inside
// World::step. Contacts against planes and between bodies, the same pairs from sweep and prune
// as from brute force, and no tunnelling of a fast thin body with continuous collision on.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "test_util.h"
#include "world/continuous_collision.h"
#include "rbsim/world/world.h"
#include "world/world_access.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxDef;

constexpr double kCollisionDt = 1.0 / 64.0;  // [s]

// Detection alone: nothing responds to the contacts, so the depths and positions below follow
// from the motion in closed form (tests/engine/dynamics covers the response).
Settings settings(const Vec3& gravity = Vec3::Zero()) {
  Settings s;
  s.respondToContacts = false;
  s.gravity = gravity;
  s.timeStep = kCollisionDt;
  s.allowSleep = false;
  return s;
}

BodyDef box(const Vec3& extents, const Vec3& position, const Vec3& velocity = Vec3::Zero()) {
  BodyDef def = boxDef(extents, 1.0);
  def.shape = Shape::box(0.5 * extents);
  def.position = position;
  def.velocity = velocity;
  return def;
}

TEST(CollisionWorld, ABoxSinkingThroughTheGroundHasFourContactsOfTheKnownDepth) {
  // The box moves down at 1 m/s through y = 0; after n steps its bottom face is
  // at 0.5 - n dt, so the depth of its four bottom corners is n dt - 0.5 once that is positive.
  // With soft step the contacts are found before the step moves the box, at the pose after
  // n - 1 steps; with PGS after. Both find them within the margin plus the step's reach dt |v|
  // (collision_pipeline.h).
  for (const auto solver : {Settings::ContactSolverMethod::Pgs, Settings::ContactSolverMethod::SoftStep}) {
  Settings s = settings();
  s.solver = solver;
  s.logQueries = true;
  const bool soft = solver == Settings::ContactSolverMethod::SoftStep;
  World world(s);
  world.addBody(box(Vec3(1.0, 1.0, 1.0), Vec3(0.0, 1.0, 0.0), Vec3(0.0, -1.0, 0.0)));
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  for (int n = 1; n <= 48; ++n) {
    world.step();
    const double depth = (soft ? n - 1 : n) * kCollisionDt - 0.5;
    if (depth < -world.settings().contactMargin - kCollisionDt * 1.0) {
      EXPECT_TRUE(world.contacts().empty()) << n;
      continue;
    }
    ASSERT_EQ(world.contacts().size(), 1u) << n;
    const Contact& c = world.contacts()[0];
    EXPECT_EQ(c.kind, Contact::Kind::PlaneBody);
    EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitY(), 0.0));
    ASSERT_EQ(c.manifold.count, 4);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(c.manifold.points[k].depth, depth, 1e-12) << n;
  }
  EXPECT_GT(WorldAccess::collision(world).queryLog().total(), 0u);
  }
}

// The query log (seed 004's debugging buffer) records only when asked: a normal run pays nothing.
// A resting box's contact is recycled after its first step (Settings::contactRecycleDistance): one
// query; collided afresh every step, four.
TEST(CollisionWorld, QueriesAreLoggedOnlyWhenAskedFor) {
  for (double recycle : {0.0, Settings{}.contactRecycleDistance}) {
    for (bool log : {false, true}) {
      Settings s = settings();
      s.logQueries = log;
      s.contactRecycleDistance = recycle;
      World world(s);
      world.addBody(box(Vec3(1.0, 1.0, 1.0), Vec3(0.0, 0.49, 0.0)));
      world.addPlane(Plane{Vec3::UnitY(), 0.0});
      for (int n = 0; n < 4; ++n) world.step();
      EXPECT_FALSE(world.contacts().empty());
      const std::size_t queries = recycle > 0.0 ? 1u : 4u;
      EXPECT_EQ(WorldAccess::collision(world).queryLog().total(), log ? queries : 0u) << recycle;
    }
  }
}

TEST(CollisionWorld, TwoBoxesOverlappingReportOneBodyContact) {
  World world(settings());
  world.addBody(box(Vec3(1.0, 1.0, 1.0), Vec3(0.0, 0.0, 0.0)));
  world.addBody(box(Vec3(1.0, 1.0, 1.0), Vec3(0.9, 0.0, 0.0)));
  world.addBody(box(Vec3(1.0, 1.0, 1.0), Vec3(5.0, 0.0, 0.0)));
  world.step();
  ASSERT_EQ(WorldAccess::collision(world).candidatePairs().size(), 1u);
  ASSERT_EQ(world.contacts().size(), 1u);
  const Contact& c = world.contacts()[0];
  EXPECT_EQ(c.kind, Contact::Kind::BodyBody);
  EXPECT_EQ(c.a, 0u);
  EXPECT_EQ(c.b, 1u);
  EXPECT_TRUE(allNear(c.manifold.normal, Vec3::UnitX(), 1e-12));
  EXPECT_NEAR(c.manifold.maxDepth(), 0.1, 1e-12);
  EXPECT_EQ(c.manifold.count, 4);
}

// A thin plate (1 cm) falling at 50 m/s: 0.78 m per step, 78 times its thickness.
World fallingPlate(bool continuous) {
  Settings s = settings();
  s.continuousCollision = continuous;
  World world(s);
  world.addBody(box(Vec3(0.5, 0.01, 0.5), Vec3(0.0, 1.0, 0.0), Vec3(0.0, -50.0, 0.0)));
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  return world;
}

TEST(CollisionWorld, AFastThinPlateDoesNotTunnelThroughAPlane) {
  // A plane is a half-space, so a body past it is still seen, as deeply penetrating: without
  // continuous collision the first contact has the whole plate below the surface.
  World without = fallingPlate(false);
  World with = fallingPlate(true);
  double firstDepth = -1.0;
  for (int n = 0; n < 10; ++n) {
    without.step();
    with.step();
    if (firstDepth < 0.0 && !without.contacts().empty()) firstDepth = without.contacts()[0].manifold.maxDepth();
  }
  EXPECT_LT(without.bodies()[0].position().y(), -5.0) << "it passed through";
  EXPECT_GT(firstDepth, 0.5) << "first seen half a metre deep, fifty times its thickness";
  // With continuous collision it stops where its bottom face is kImpactSeparation or less above
  // the plane, and the narrow phase sees it.
  const double bottom = with.bodies()[0].position().y() - 0.005;
  EXPECT_GE(bottom, 0.0);
  EXPECT_LE(bottom, kImpactSeparation);
  EXPECT_FALSE(with.contacts().empty());
  EXPECT_GT(with.stageStats(Stage::ContinuousCollision).runs, 0u);
}

TEST(CollisionWorld, AFastBoxDoesNotTunnelThroughAStaticWall) {
  for (bool continuous : {false, true}) {
    Settings s = settings();
    s.continuousCollision = continuous;
    World world(s);
    world.addBody(box(Vec3(0.1, 0.1, 0.1), Vec3(-1.0, 0.0, 0.0), Vec3(120.0, 0.0, 0.0)));
    BodyDef wall = box(Vec3(0.05, 2.0, 2.0), Vec3(0.0, 0.0, 0.0));
    wall.isStatic = true;
    world.addBody(wall);
    for (int n = 0; n < 8; ++n) world.step();
    const double front = world.bodies()[0].position().x() + 0.05;
    if (continuous) {
      EXPECT_LE(front, -0.025 + 1e-9) << "stopped before the wall's face";
      EXPECT_GE(front, -0.025 - kImpactSeparation - 1e-9);
      EXPECT_FALSE(WorldAccess::collision(world).impacts().empty());
    } else {
      EXPECT_GT(front, 5.0) << "without protection it went through";
    }
  }
}

TEST(CollisionWorld, WithResponseAFastThinPlateLandsAndRestsOnThePlane) {
  // A 1 cm plate is the worst-conditioned resting contact. PGS keeps it rocking at ~1 cm/s with
  // its default 10 sweeps and needs 50 to bring it to rest; soft step rests it with its defaults.
  for (const auto solver : {Settings::ContactSolverMethod::Pgs, Settings::ContactSolverMethod::SoftStep}) {
    Settings s = settings(Vec3(0.0, -9.81, 0.0));
    s.respondToContacts = true;
    s.solver = solver;
    if (solver == Settings::ContactSolverMethod::Pgs) {
      s.velocityIterations = 50;
      // PGS integrates before it solves (Catto 2005): these figures are its own with the
      // forward-Euler drift x += dt v it was tuned with; exact's drift carries g dt^2 / 2 more a
      // step, which PGS pushes back out (docs/integrators.md).
      s.integrator = Integrator::ExpMap;
    }
    World world(s);
    world.addBody(box(Vec3(0.5, 0.01, 0.5), Vec3(0.0, 1.0, 0.0), Vec3(0.0, -50.0, 0.0)));
    world.addPlane(Plane{Vec3::UnitY(), 0.0});
    for (int n = 0; n < 128; ++n) {
      world.step();
      const double bottom = world.bodies()[0].position().y() - 0.005;
      EXPECT_GT(bottom, -(s.contactSlop + 1e-3)) << "penetration beyond the slop at step " << n;
    }
    EXPECT_LT(world.bodies()[0].velocity().norm(), 1e-3);
    EXPECT_LT(world.bodies()[0].angularVelocity().norm(), 1e-2);
  }
}

TEST(CollisionWorld, SweepAndPruneAndBruteForceGiveTheSameContacts) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<World, 2> worlds{World(settings()), World(settings())};
  Settings brute = settings();
  brute.broadPhase = Settings::BroadPhaseMethod::BruteForce;
  worlds[1] = World(brute);
  for (int i = 0; i < 150; ++i) {
    const Vec3 x(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng)), v(u(rng), u(rng), u(rng));
    for (World& w : worlds) {
      BodyDef def = box(Vec3(0.5, 0.3, 0.2), x, 2.0 * v);
      def.angularVelocity = 3.0 * v;
      w.addBody(def);
    }
  }
  for (int n = 0; n < 40; ++n) {
    for (World& w : worlds) w.step();
    ASSERT_EQ(WorldAccess::collision(worlds[0]).candidatePairs(), WorldAccess::collision(worlds[1]).candidatePairs()) << n;
    ASSERT_EQ(worlds[0].contacts().size(), worlds[1].contacts().size()) << n;
  }
  EXPECT_GT(worlds[0].contacts().size(), 0u) << "the scene has contacts to compare";
}

TEST(CollisionWorld, CollisionStagesAreSkippedWithNothingToCollide) {
  World lonely(settings());
  lonely.addBody(box(Vec3::Ones(), Vec3::Zero(), Vec3(1.0, 0.0, 0.0)));
  Settings off = settings();
  off.detectCollisions = false;
  World passing(off);
  passing.addBody(box(Vec3::Ones(), Vec3::Zero(), Vec3(1.0, 0.0, 0.0)));
  passing.addBody(box(Vec3::Ones(), Vec3(0.5, 0.0, 0.0)));
  passing.addPlane(Plane{Vec3::UnitY(), 0.0});
  for (int n = 0; n < 5; ++n) {
    lonely.step();
    passing.step();
  }
  for (Stage s : {Stage::ContinuousCollision, Stage::BroadPhase, Stage::NarrowPhase}) {
    EXPECT_EQ(lonely.stageStats(s).runs, 0u) << stageName(s);
    EXPECT_EQ(passing.stageStats(s).runs, 0u) << stageName(s);
  }
  EXPECT_TRUE(passing.contacts().empty()) << "overlapping, but collisions are off";
}

// A box tumbling onto the ground: continuous collision stops its swinging corners, and contacts
// must take the speed it had, with either solver. Before PGS had speculative contacts (the
// step's reach) a box spinning at 20-30 rad/s was stopped at its corner's impact every step with
// no contact to answer it, and gained g dt of speed a step: up to 9.9 kJ from 0.97 kJ.
TEST(CollisionWorld, ATumblingBoxLandsWithoutGainingEnergyWithEitherSolver) {
  for (const auto solver : {Settings::ContactSolverMethod::Pgs, Settings::ContactSolverMethod::SoftStep}) {
    for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
      for (const Vec3& spin : {Vec3(15.0, 2.0, 20.0), Vec3(30.0, 5.0, 10.0), Vec3(20.0, 20.0, 20.0)}) {
        for (const double height : {0.3, 0.6, 1.0}) {
          Settings s;
          s.solver = solver;
          s.timeStep = dt;
          World world(s);
          world.addPlane(Plane{});
          BodyDef def = box(Vec3::Constant(0.4), Vec3(0.0, height, 0.0), Vec3(0.0, -3.0, 0.0));
          def.mass = 32.0;  // 500 kg/m^3
          def.inertiaBody = Mat3::Identity() * (32.0 * 0.32 / 12.0);
          def.angularVelocity = spin;
          world.addBody(def);
          const RigidBody& b = world.bodies()[0];
          const auto energy = [&] { return b.kineticEnergy() - b.mass() * s.gravity.dot(b.position()); };
          const double start = energy();
          double lowest = start, rise = 0.0;
          while (world.time() < 4.0) {
            world.step();
            lowest = std::min(lowest, energy());
            rise = std::max(rise, energy() - lowest);
          }
          const std::string where = (solver == Settings::ContactSolverMethod::Pgs ? "pgs" : "soft step") +
                                    std::string(", dt ") + std::to_string(dt) + ", height " + std::to_string(height);
          EXPECT_LT(rise, 0.005 * start) << where;  // contacts only take energy away
          EXPECT_LT(b.velocity().norm(), 0.01) << where;  // and it comes to rest
        }
      }
    }
  }
}

TEST(ContinuousCollision, ConservativeAdvancementFindsTheAnalyticTimeOfImpact) {
  // A unit cube's bottom at y = 1.5 moving down 4 m in the step reaches the plane at s = 0.375;
  // conservative advancement stops with the face in (0, kImpactSeparation] above it.
  const Shape cube = Shape::box(Vec3::Constant(0.5));
  SweptBody swept{&cube, nullptr, {}, {}, std::sqrt(0.75)};
  swept.start.position = Vec3(0.0, 2.0, 0.0);
  swept.end.position = Vec3(0.0, -2.0, 0.0);
  const auto s = timeOfImpact(swept, Plane{Vec3::UnitY(), 0.0});
  ASSERT_TRUE(s.has_value());
  const double gap = 1.5 - 4.0 * *s;  // bottom face height at s [m]
  EXPECT_GT(gap, 0.0) << "never past the plane";
  EXPECT_LE(gap, kImpactSeparation + 1e-12) << "stopped within the separation band";
  // Moving away from a plane it touches is no impact.
  swept.start.position = Vec3(0.0, 0.5, 0.0);
  swept.end.position = Vec3(0.0, 3.0, 0.0);
  EXPECT_FALSE(timeOfImpact(swept, Plane{Vec3::UnitY(), 0.0}).has_value());
}

}  // namespace
}  // namespace rbsim
