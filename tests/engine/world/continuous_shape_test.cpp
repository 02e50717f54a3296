// world/continuous_collision sweeps the collision shape, not the display mesh (issue 56): a body
// whose mesh is larger than its shape comes to rest on its shape without gaining energy, against
// a plane (the plane sweep) and against a static box (the pair sweep), and a fast body whose
// display mesh is smaller than its shape (a sphere's inscribed mesh) still stops at a thin wall.
#include <algorithm>
#include <memory>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/world/world.h"
#include "world/continuous_collision.h"
#include "world/world_access.h"

namespace rbsim {
namespace {

constexpr double kShapeDt = 1.0 / 60.0;        // [s], Box2D's and rbsim's default step
constexpr double kBallRadius = 0.25;           // [m], the collision shape
constexpr double kMeshRadius = 0.5;            // [m], the display mesh around it, twice as large
constexpr double kBallMass = 1.0;              // [kg]
constexpr double kDropSpeed = 30.0;            // [m/s] down: 0.5 m a step, twice the shape's radius
constexpr double kDropHeight = 3.0;            // [m], the centre at the start
constexpr double kSettleSeconds = 2.0;         // [s]: the drop takes 0.1 s, the rest is resting
// Energy a contact may appear to add through the soft step's rounding and its slop push-out: the
// push-out is at most contactSlop of height, m g slop = 0.05 J for 1 kg; a hanging body gained
// m g (dt v) every step instead, 0.5 J a step from the first one.
constexpr double kEnergyRiseTolerance = 0.06;  // [J]

// A sphere of radius kBallRadius drawn as a UV sphere of kMeshRadius around it.
BodyDef ballInBigMesh(const Vec3& position, const Vec3& velocity) {
  BodyDef def = shapeBodyDef(Shape::sphere(kBallRadius), kBallMass, "ball");
  def.mesh = std::make_shared<const Mesh>(makeUvSphere(kMeshRadius, kDisplaySegments, kDisplayRings));
  def.position = position;
  def.velocity = velocity;
  return def;
}

Settings droppingSettings() {
  Settings s;
  s.timeStep = kShapeDt;
  s.gravity = Vec3(0.0, -9.81, 0.0);
  s.allowSleep = false;
  s.continuousCollision = true;
  return s;
}

// Runs the world for kSettleSeconds; returns the largest rise of the ball's energy (kinetic plus
// potential) above the least it had reached before [J].
double energyRise(World& world, std::size_t ball) {
  const RigidBody& b = world.bodies()[ball];
  const auto energy = [&] { return b.kineticEnergy() - b.mass() * world.settings().gravity.dot(b.position()); };
  double lowest = energy(), rise = 0.0;
  while (world.time() < kSettleSeconds) {
    world.step();
    lowest = std::min(lowest, energy());
    rise = std::max(rise, energy() - lowest);
  }
  return rise;
}

TEST(ContinuousShape, ABallInABigMeshFallingFastRestsOnItsShapeOnAPlane) {
  World world(droppingSettings());
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  world.addBody(ballInBigMesh(Vec3(0.0, kDropHeight, 0.0), Vec3(0.0, -kDropSpeed, 0.0)));
  const double rise = energyRise(world, 0);
  const RigidBody& b = world.bodies()[0];
  // At rest the soft step holds a contact at most contactSlop deep (settings.h), and the sweep
  // leaves a body at most kImpactSeparation above: the centre is within those of the radius.
  EXPECT_GE(b.position().y(), kBallRadius - world.settings().contactSlop - kImpactSeparation);
  EXPECT_LE(b.position().y(), kBallRadius + kImpactSeparation);
  EXPECT_LT(b.velocity().norm(), 1e-2) << "at rest, not held up while gravity adds to its momentum";
  EXPECT_LT(rise, kEnergyRiseTolerance);
}

TEST(ContinuousShape, ABallInABigMeshFallingFastRestsOnItsShapeOnAStaticBox) {
  // The pair sweep (GJK between the shapes' cores): the ground is a static box whose top is y = 0.
  World world(droppingSettings());
  BodyDef ground = shapeBodyDef(Shape::box(Vec3(5.0, 0.5, 5.0)), 1.0, "ground");
  ground.position = Vec3(0.0, -0.5, 0.0);
  ground.isStatic = true;
  world.addBody(ground);
  world.addBody(ballInBigMesh(Vec3(0.0, kDropHeight, 0.0), Vec3(0.0, -kDropSpeed, 0.0)));
  const double rise = energyRise(world, 1);
  const RigidBody& b = world.bodies()[1];
  EXPECT_GE(b.position().y(), kBallRadius - world.settings().contactSlop - kImpactSeparation);
  EXPECT_LE(b.position().y(), kBallRadius + kImpactSeparation);
  EXPECT_LT(b.velocity().norm(), 1e-2);
  EXPECT_LT(rise, kEnergyRiseTolerance);
}

TEST(ContinuousShape, SweptGapIsTheShapesNotTheMeshes) {
  // Two balls on the x axis, centres 2 m apart, closing at 4 m per unit s: the shapes (radius
  // 0.25) meet after 1.5 m of closing, at s = 0.375; the meshes (0.5) would at s = 0.25.
  const Shape ball = Shape::sphere(kBallRadius);
  SweptBody a{&ball, nullptr, {}, {}, kBallRadius}, b{&ball, nullptr, {}, {}, kBallRadius};
  a.start.position = Vec3(-1.0, 0.0, 0.0);
  a.end.position = Vec3(1.0, 0.0, 0.0);
  b.start.position = Vec3(1.0, 0.0, 0.0);
  b.end.position = Vec3(-1.0, 0.0, 0.0);
  const auto s = timeOfImpact(a, b);
  ASSERT_TRUE(s.has_value());
  const double gap = 1.5 - 4.0 * *s;  // [m] between the spheres at s
  EXPECT_GT(gap, 0.0);
  EXPECT_LE(gap, kImpactSeparation + 1e-12);
  // A capsule standing on its end: its lowest point is r + h below its centre.
  const Shape capsule = Shape::capsule(0.1, 0.4);
  SweptBody c{&capsule, nullptr, {}, {}, 0.5};
  c.start.position = Vec3(0.0, 2.0, 0.0);
  c.end.position = Vec3(0.0, -2.0, 0.0);
  const auto t = timeOfImpact(c, Plane{Vec3::UnitY(), 0.0});
  ASSERT_TRUE(t.has_value());
  const double bottom = 2.0 - 4.0 * *t - 0.5;  // [m]
  EXPECT_GT(bottom, 0.0);
  EXPECT_LE(bottom, kImpactSeparation + 1e-12);
}

TEST(ContinuousShape, AFastBallStillStopsAtAThinWall) {
  // 200 m/s is 3.3 m a step against a 2 cm wall; the ball's display mesh is inscribed in its
  // shape, so the sweep must stop the shape, not the smaller mesh, at the wall's face.
  constexpr double kSpeed = 200.0;       // [m/s]
  constexpr double kWallHalf = 0.01;     // [m], half the wall's thickness
  for (const bool continuous : {false, true}) {
    Settings s = droppingSettings();
    s.gravity = Vec3::Zero();
    s.respondToContacts = false;  // detection alone: the stop is the sweep's, in closed form
    s.continuousCollision = continuous;
    World world(s);
    BodyDef ballDef = shapeBodyDef(Shape::sphere(kBallRadius), kBallMass, "ball");
    ballDef.position = Vec3(-2.0, 0.0, 0.0);
    ballDef.velocity = Vec3(kSpeed, 0.0, 0.0);
    world.addBody(ballDef);
    BodyDef wall = shapeBodyDef(Shape::box(Vec3(kWallHalf, 2.0, 2.0)), 1.0, "wall");
    wall.isStatic = true;
    world.addBody(wall);
    for (int n = 0; n < 4; ++n) world.step();
    const double front = world.bodies()[0].position().x() + kBallRadius;
    if (continuous) {
      EXPECT_LE(front, -kWallHalf) << "never past the wall's face";
      EXPECT_GE(front, -kWallHalf - kImpactSeparation) << "stopped within the separation band";
      EXPECT_FALSE(WorldAccess::collision(world).impacts().empty());
    } else {
      EXPECT_GT(front, 5.0) << "without the sweep it went through";
    }
  }
}

TEST(ContinuousShape, AFastBallBouncesOffAThinWallAndNeverCrossesIt) {
  // With the response on, over a second: it stops at the wall and the contact sends it back.
  constexpr double kSpeed = 200.0;    // [m/s]
  constexpr double kWallHalf = 0.01;  // [m]
  Settings s = droppingSettings();
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef ballDef = ballInBigMesh(Vec3(-2.0, 0.0, 0.0), Vec3(kSpeed, 0.0, 0.0));
  ballDef.mesh = std::make_shared<const Mesh>(makeUvSphere(kBallRadius, kDisplaySegments, kDisplayRings));
  world.addBody(ballDef);
  BodyDef wall = shapeBodyDef(Shape::box(Vec3(kWallHalf, 2.0, 2.0)), 1.0, "wall");
  wall.isStatic = true;
  world.addBody(wall);
  double furthest = -10.0;
  while (world.time() < 1.0) {
    world.step();
    furthest = std::max(furthest, world.bodies()[0].position().x() + kBallRadius);
  }
  EXPECT_LE(furthest, -kWallHalf + world.settings().contactSlop) << "into the wall by at most the slop";
  EXPECT_LE(world.bodies()[0].velocity().x(), 0.0) << "sent back, or stopped";
}

}  // namespace
}  // namespace rbsim
