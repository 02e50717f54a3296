// Particles against planes and rigid bodies: never left behind a surface, bouncing with the
// restitution asked for, and slowed by friction while sliding.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include "particle_test_util.h"
#include "rbsim/world/systems.h"
#include "rbsim/particles/particle_collision.h"

namespace rbsim {
namespace {

using test::particleSettings;
using test::singleParticle;
using test::stepN;

ParticleSystemDef spray(double radius) {
  ParticleSystemDef def;
  def.capacity = 4000;
  def.seed = 9;
  EmitterDef e;
  e.shape = EmitterShape::Box;
  e.position = Vec3(0.0, 2.0, 0.0);
  e.halfExtents = Vec3(1.0, 0.5, 1.0);
  e.direction = Vec3(0.0, -1.0, 0.0);
  e.spreadDegrees = 80.0;
  e.speedMin = 5.0;
  e.speedMax = 40.0;  // up to 0.17 m per step: far deeper than any surface in one step
  e.rate = 4000.0;
  e.lifetimeMin = e.lifetimeMax = 1.5;
  def.emitters.push_back(e);
  def.collision.restitution = 0.5;
  def.collision.radius = radius;
  return def;
}

TEST(ParticleCollision, NeverLeavesAParticleBelowAPlane) {
  for (double radius : {0.0, 0.02}) {
    World world(particleSettings(1.0 / 240.0, Vec3(0.0, -9.81, 0.0)));
    world.addPlane(Plane{Vec3::UnitY(), 0.0});
    world.addPlane(Plane{Vec3(1.0, 1.0, 0.0).normalized(), -0.5});  // a slope through the spray
    addParticleSystem(world, spray(radius));
    const ParticleStore& p = particleSystems(world)[0].particles();
    double lowest = std::numeric_limits<double>::infinity();
    std::size_t checked = 0;
    for (int s = 0; s < 480; ++s) {
      world.step();
      for (std::size_t i = 0; i < p.count(); ++i) {
        lowest = std::min(lowest, p.position[i].y() - radius);
        ++checked;
      }
    }
    EXPECT_GT(checked, 100000u);
    EXPECT_GE(lowest, -1e-12) << "radius " << radius;
  }
}

TEST(ParticleCollision, WithoutCollisionsTheSameSprayFallsThrough) {
  // The control for the test above: it fails if collisions do nothing.
  World world(particleSettings(1.0 / 240.0, Vec3(0.0, -9.81, 0.0)));
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  ParticleSystemDef def = spray(0.0);
  def.collision.planes = false;
  addParticleSystem(world, def);
  stepN(world, 120);
  const ParticleStore& p = particleSystems(world)[0].particles();
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.count(); ++i) lowest = std::min(lowest, p.position[i].y());
  EXPECT_LT(lowest, -1.0);
}

TEST(ParticleCollision, NeverLeavesAParticleInsideARigidBox) {
  World world(particleSettings(1.0 / 240.0, Vec3(0.0, -9.81, 0.0)));
  BodyDef box;
  box.name = "box";
  box.mesh = std::make_shared<Mesh>(makeBox(Vec3(1.2, 0.6, 0.8)));
  box.isStatic = true;
  box.position = Vec3(0.2, 0.3, 0.0);
  box.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY()));
  world.addBody(box);
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  addParticleSystem(world, spray(0.0));
  const FacePlanes shape = facePlanesOf(world.bodies()[0].mesh());
  ASSERT_EQ(shape.normals.size(), 6u);
  const ParticleStore& p = particleSystems(world)[0].particles();
  const RigidBody& body = world.bodies()[0];
  double deepest = -std::numeric_limits<double>::infinity();  // most negative signed distance, negated
  for (int s = 0; s < 360; ++s) {
    world.step();
    for (std::size_t i = 0; i < p.count(); ++i) {
      const Vec3 local = body.rotation().transpose() * (p.position[i] - body.position());
      double outside = -std::numeric_limits<double>::infinity();
      for (std::size_t f = 0; f < shape.normals.size(); ++f) outside = std::max(outside, shape.normals[f].dot(local) - shape.offsets[f]);
      deepest = std::max(deepest, -outside);
    }
  }
  EXPECT_LE(deepest, 1e-12);
}

TEST(ParticleCollision, BouncesWithTheRestitutionAndSlidesWithFriction) {
  ParticleCollisionDef c;
  c.restitution = 0.6;
  c.friction = 0.2;
  Vec3 x(0.0, -0.01, 0.0), v(3.0, -2.0, 0.0);
  ASSERT_TRUE(collidePlane(x, v, Plane{Vec3::UnitY(), 0.0}, c));
  EXPECT_DOUBLE_EQ(x.y(), 0.0);
  EXPECT_NEAR(v.y(), 1.2, 1e-15);                       // -e v_n
  EXPECT_NEAR(v.x(), 3.0 - 0.2 * 1.6 * 2.0, 1e-15);     // |dv_t| = mu (1 + e) |v_n|
  Vec3 slow(0.1, -2.0, 0.0);
  x = Vec3(0.0, -0.01, 0.0);
  collidePlane(x, slow, Plane{Vec3::UnitY(), 0.0}, c);
  EXPECT_EQ(slow.x(), 0.0) << "inside the friction cone it sticks";
}

TEST(ParticleCollision, AMovingBodyThrowsAParticleAlong) {
  World world(particleSettings(1e-3, Vec3::Zero()));
  BodyDef box;
  box.name = "paddle";
  box.mesh = std::make_shared<Mesh>(makeBox(Vec3(1.0, 1.0, 1.0)));
  box.velocity = Vec3(2.0, 0.0, 0.0);
  world.addBody(box);
  ParticleSystemDef def = singleParticle(0.01, Vec3(0.55, 0.0, 0.0), Vec3::Zero());
  def.collision.bodies = true;
  def.collision.restitution = 1.0;
  addParticleSystem(world, def);
  stepN(world, 100);
  // An elastic hit by a wall at 2 m/s leaves at 4 m/s (relative velocity reversed).
  EXPECT_NEAR(particleSystems(world)[0].particles().velocity[0].x(), 4.0, 1e-9);
}

}  // namespace
}  // namespace rbsim
