// Emitters: the live count settles at rate x lifetime, a full store refuses births without
// growing, every sample lands in the emitter's shape, and a seed fixes the whole run.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "rbsim/world/systems.h"
#include "particle_test_util.h"

namespace rbsim {
namespace {

using test::particleSettings;
using test::stepN;

ParticleSystemDef fountain(double rate, double lifetime, std::uint64_t seed = 1) {
  ParticleSystemDef def;
  def.seed = seed;
  def.capacity = 100000;
  EmitterDef e;
  e.shape = EmitterShape::Disc;
  e.radius = 0.2;
  e.rate = rate;
  e.speedMin = 2.0;
  e.speedMax = 6.0;
  e.spreadDegrees = 20.0;
  e.lifetimeMin = e.lifetimeMax = lifetime;
  e.massMin = 0.01;
  e.massMax = 0.03;
  def.emitters.push_back(e);
  return def;
}

TEST(Emitter, RateTimesLifetimeGivesTheLiveCount) {
  const double dt = 1.0 / 240.0;
  for (const auto& [rate, lifetime] : {std::pair{100.0, 1.0}, std::pair{1000.0, 0.5}, std::pair{37.0, 2.5}}) {
    World world(particleSettings(dt, Vec3(0.0, -9.81, 0.0)));
    world.addPlane(Plane{});
    addParticleSystem(world, fountain(rate, lifetime));
    const int steps = static_cast<int>(std::ceil(1.5 * lifetime / dt));
    stepN(world, steps);
    const double live = static_cast<double>(particleSystems(world)[0].particles().count());
    // Births in the last `lifetime` seconds, within one step's births of R L.
    EXPECT_NEAR(live, rate * lifetime, rate * dt + 1.0) << rate << " /s, " << lifetime << " s";
    EXPECT_NEAR(static_cast<double>(particleSystems(world)[0].emitted()), rate * steps * dt, 1.0);
  }
}

TEST(Emitter, AFullStoreRefusesBirthsAndCountsThem) {
  World world(particleSettings(0.01, Vec3::Zero()));
  ParticleSystemDef def = fountain(1000.0, 10.0);
  def.capacity = 50;
  addParticleSystem(world, def);
  const ParticleStore& p = particleSystems(world)[0].particles();
  const Vec3* storage = p.position.data();
  stepN(world, 10);  // 100 due
  EXPECT_EQ(p.count(), 50u);
  EXPECT_EQ(particleSystems(world)[0].emitted(), 50u);
  // Of the 100 due, 10 a step (rate dt accumulated in floating point: 99 or 100).
  EXPECT_NEAR(static_cast<double>(particleSystems(world)[0].lost()), 50.0, 1.0);
  EXPECT_EQ(p.position.data(), storage) << "no reallocation";
}

TEST(Emitter, SamplesLieInTheirShapesAndCone) {
  const double dt = 0.01;
  World world(particleSettings(dt, Vec3::Zero()));
  ParticleSystemDef def = fountain(0.0, 1.0);
  EmitterDef& e = def.emitters[0];
  e.burst = 2000;
  e.direction = Vec3(1.0, 1.0, 0.0).normalized();
  e.position = Vec3(1.0, 2.0, 3.0);
  e.speedMin = e.speedMax = 0.0;  // stay where born
  addParticleSystem(world, def);
  world.step();
  const ParticleStore& p = particleSystems(world)[0].particles();
  ASSERT_EQ(p.count(), 2000u);
  double farthest = 0.0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const Vec3 d = p.position[i] - e.position;
    EXPECT_NEAR(d.dot(e.direction), 0.0, 1e-12) << "in the disc's plane";
    farthest = std::max(farthest, d.norm());
  }
  EXPECT_LE(farthest, e.radius + 1e-12);
  EXPECT_GT(farthest, 0.95 * e.radius);

  // Mesh surface of a rotated box: every particle on a face, launched outward.
  World boxWorld(particleSettings(dt, Vec3::Zero()));
  BodyDef box;
  box.name = "box";
  box.mesh = std::make_shared<Mesh>(makeBox(Vec3(2.0, 1.0, 0.5)));
  box.isStatic = true;
  box.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 0.5).normalized()));
  boxWorld.addBody(box);
  ParticleSystemDef meshDef = fountain(0.0, 1.0);
  meshDef.emitters[0].shape = EmitterShape::MeshSurface;
  meshDef.emitters[0].burst = 500;
  meshDef.emitters[0].spreadDegrees = 0.0;
  meshDef.emitters[0].speedMin = meshDef.emitters[0].speedMax = 1.0;
  meshDef.collision.bodies = false;
  addParticleSystem(boxWorld, meshDef);
  boxWorld.step();
  const ParticleStore& q = particleSystems(boxWorld)[0].particles();
  const RigidBody& body = boxWorld.bodies()[0];
  for (std::size_t i = 0; i < q.count(); ++i) {
    const Vec3 local = body.rotation().transpose() * (q.position[i] - dt * q.velocity[i]);  // where born
    const Vec3 out = body.rotation().transpose() * q.velocity[i];
    const Vec3 half(1.0, 0.5, 0.25);
    const double onFace = ((local.cwiseAbs() - half).cwiseAbs().array() < 1e-9).count();
    EXPECT_GE(onFace, 1) << local.transpose();
    EXPECT_LE((local.cwiseAbs() - half).maxCoeff(), 1e-9);
    EXPECT_GT(out.dot(local), 0.0) << "launched outward";
  }
}

TEST(Emitter, AFixedSeedGivesIdenticalRunsAndAnotherSeedDoesNot) {
  const auto run = [](std::uint64_t seed) {
    World world(particleSettings(1.0 / 240.0, Vec3(0.0, -9.81, 0.0)));
    world.addPlane(Plane{});
    ParticleSystemDef def = fountain(800.0, 1.5, seed);
    def.dragLinear = 0.002;
    def.wind.velocity = Vec3(1.0, 0.0, 0.0);
    def.wind.turbulence = 2.0;
    addParticleSystem(world, def);
    stepN(world, 400);
    return world.stateHash();
  };
  EXPECT_EQ(run(7), run(7));
  EXPECT_NE(run(7), run(8));
}

}  // namespace
}  // namespace rbsim
