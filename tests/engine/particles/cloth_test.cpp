// The spring cloth: springs act in equal and opposite pairs, so without external forces the
// cloth's linear momentum stays what it was, whatever the springs do to its shape.
#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "rbsim/world/systems.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/integrate/simulation_error.h"
#include "particle_test_util.h"

namespace rbsim {
namespace {

using test::particleSettings;
using test::stepN;

ParticleSystemDef freeCloth(ParticleIntegrator integrator) {
  ParticleSystemDef def;
  def.integrator = integrator;
  def.capacity = 12 * 9;
  def.cloth.enabled = true;
  def.cloth.nu = 12;
  def.cloth.nv = 9;
  def.cloth.edgeU = Vec3(1.1, 0.0, 0.0);
  def.cloth.edgeV = Vec3(0.0, 0.2, 0.8);
  def.cloth.mass = 0.3;
  // Node mass 2.8 g: the stiffest mode's omega dt stays near 1.4 at 240 steps/s, below the
  // semi-implicit step's limit of 2.
  def.cloth.stiffness = 10.0;
  def.cloth.bendStiffness = 1.0;
  def.cloth.damping = 0.01;
  def.collision.planes = false;
  def.collision.bodies = false;
  return def;
}

// Every node gets a random velocity: the springs stretch and swing, and the momentum must stay.
World shakenCloth(ParticleIntegrator integrator) {
  World world(particleSettings(1.0 / 240.0, Vec3::Zero()));
  addParticleSystem(world, freeCloth(integrator));
  ParticleStore& p = particleSystems(world)[0].particles();
  UniformRandom random(42);
  for (std::size_t i = 0; i < p.count(); ++i) p.velocity[i] = random.between(0.0, 1.5) * random.direction();
  return world;
}

TEST(Cloth, BuildsTheGridItsDefinitionAsksFor) {
  World world(particleSettings(1.0 / 240.0, Vec3::Zero()));
  addParticleSystem(world, freeCloth(ParticleIntegrator::SemiImplicitEuler));
  const ParticleSystem& cloth = particleSystems(world)[0];
  EXPECT_EQ(cloth.particles().count(), 108u);
  EXPECT_EQ(cloth.clothTriangles().size(), 2u * 11u * 8u);
  // Structural 11*9 + 12*8, shear 2*11*8, bend 10*9 + 12*7.
  EXPECT_EQ(cloth.springs().size(), 99u + 96u + 176u + 90u + 84u);
  EXPECT_NEAR(cloth.particles().mass(0) * 108.0, 0.3, 1e-12);
}

// Sum of m |v|: the scale momentum errors are measured against [kg m/s].
double momentumScale(const ParticleStore& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.count(); ++i) sum += p.mass(i) * p.velocity[i].norm();
  return sum;
}

TEST(Cloth, ConservesLinearMomentumWithoutExternalForces) {
  // Explicit Euler gains energy on these springs and is run for fewer steps.
  for (const auto& [integrator, steps] : {std::pair{ParticleIntegrator::SemiImplicitEuler, 480},
                                          std::pair{ParticleIntegrator::ExplicitEuler, 24}}) {
    World world = shakenCloth(integrator);
    const ParticleStore& p = particleSystems(world)[0].particles();
    const Vec3 before = p.momentum();
    const Vec3 start = p.position[0];
    stepN(world, steps);
    EXPECT_LT((p.momentum() - before).norm(), 1e-13 * momentumScale(p)) << particleIntegratorName(integrator);
    EXPECT_GT((p.position[0] - start).norm(), 0.01) << "the cloth moved";
  }
}

// Kinetic energy plus the springs' potential energy k (|d| - L0)^2 / 2 [J].
double energy(const ParticleSystem& cloth) {
  const ParticleStore& p = cloth.particles();
  double e = 0.0;
  for (std::size_t i = 0; i < p.count(); ++i) e += 0.5 * p.mass(i) * p.velocity[i].squaredNorm();
  for (const ParticleSpring& s : cloth.springs()) {
    const double stretch = (p.position[s.b] - p.position[s.a]).norm() - s.restLength;
    e += 0.5 * s.stiffness * stretch * stretch;
  }
  return e;
}

TEST(Cloth, ExplicitEulerGainsEnergySemiImplicitEulerDoesNot) {
  World semi = shakenCloth(ParticleIntegrator::SemiImplicitEuler);
  World explicitEuler = shakenCloth(ParticleIntegrator::ExplicitEuler);
  const double before = energy(particleSystems(semi)[0]);
  stepN(semi, 240);
  stepN(explicitEuler, 240);
  EXPECT_LT(energy(particleSystems(semi)[0]), before) << "damped springs lose energy";
  EXPECT_GT(energy(particleSystems(explicitEuler)[0]), 100.0 * before);
}

TEST(Cloth, AStretchedSpringPullsItsEndsTogether) {
  World world(particleSettings(1e-3, Vec3::Zero()));
  ParticleSystemDef def = freeCloth(ParticleIntegrator::SemiImplicitEuler);
  def.cloth.nu = def.cloth.nv = 2;
  addParticleSystem(world, def);
  ParticleStore& p = particleSystems(world)[0].particles();
  p.position[1].x() += 0.5;  // node (1, 0) pulled away along +x
  world.step();
  EXPECT_LT(p.velocity[1].x(), 0.0);
  EXPECT_GT(p.velocity[0].x(), 0.0);
}

TEST(Cloth, PinnedNodesStayWhereTheyAre) {
  World world(particleSettings(1.0 / 240.0, Vec3(0.0, -9.81, 0.0)));
  ParticleSystemDef def = freeCloth(ParticleIntegrator::SemiImplicitEuler);
  def.cloth.pinned = {{0, 0}, {11, 0}};
  def.substeps = 4;
  addParticleSystem(world, def);
  const ParticleStore& p = particleSystems(world)[0].particles();
  const Vec3 corner = p.position[11];
  const double y50 = p.position[50].y();
  stepN(world, 240);
  EXPECT_EQ(p.position[11], corner);
  EXPECT_LT(p.position[50].y(), y50 - 0.1) << "the free nodes fall";
}

TEST(Cloth, ADivergingClothStopsTheRunNamingItsIntegrator) {
  World world = shakenCloth(ParticleIntegrator::ExplicitEuler);
  try {
    stepN(world, 100000);
    FAIL() << "explicit Euler on these springs was expected to diverge";
  } catch (const SimulationError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("explicit-euler"), std::string::npos) << message;
    EXPECT_NE(message.find("particle system 'particles'"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace rbsim
