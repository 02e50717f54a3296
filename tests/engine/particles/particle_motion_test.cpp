// F = ma for particles (seed 000's homework): the projectile against its closed form, drag
// against its terminal velocity m g / k, and the two integrators' known first-order errors.
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/world/systems.h"
#include "particle_test_util.h"

namespace rbsim {
namespace {

using test::particleSettings;
using test::singleParticle;
using test::stepN;

const Vec3 kGravity(0.0, -9.81, 0.0);  // [m/s^2]

struct Flight {
  Vec3 position, velocity;
};

// The particle is launched in the first step (it moves for that step too), so after n steps it
// has flown t = n dt.
Flight fly(ParticleIntegrator integrator, double dt, int steps, const Vec3& x0, const Vec3& v0) {
  World world(particleSettings(dt, kGravity));
  ParticleSystemDef def = singleParticle(0.2, x0, v0);
  def.integrator = integrator;
  addParticleSystem(world, def);
  stepN(world, steps);
  const ParticleStore& p = particleSystems(world)[0].particles();
  EXPECT_EQ(p.count(), 1u);
  return {p.position[0], p.velocity[0]};
}

TEST(Projectile, SemiImplicitEulerMatchesTheClosedFormToFirstOrder) {
  const Vec3 x0(0.0, 1.0, 0.0), v0(3.0, 8.0, -1.0);
  const double dt = 1e-3;
  const int n = 1000;
  const double t = n * dt;
  const Flight f = fly(ParticleIntegrator::SemiImplicitEuler, dt, n, x0, v0);
  const Vec3 exact = x0 + v0 * t + 0.5 * kGravity * t * t;
  // v_n is exact under a constant force; x_n = exact + g t dt / 2 (the sum of k dt g dt, k = 1..n).
  EXPECT_NEAR((f.velocity - (v0 + kGravity * t)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f.position - (exact + 0.5 * kGravity * t * dt)).norm(), 0.0, 1e-9);
  EXPECT_LT((f.position - exact).norm(), 0.5 * kGravity.norm() * t * dt * 1.0001);
}

TEST(Projectile, ExplicitEulerLagsTheClosedFormByHalfGTDt) {
  const Vec3 x0(0.0, 1.0, 0.0), v0(3.0, 8.0, -1.0);
  const double dt = 1e-3;
  const int n = 1000;
  const double t = n * dt;
  const Flight f = fly(ParticleIntegrator::ExplicitEuler, dt, n, x0, v0);
  const Vec3 exact = x0 + v0 * t + 0.5 * kGravity * t * t;
  EXPECT_NEAR((f.position - (exact - 0.5 * kGravity * t * dt)).norm(), 0.0, 1e-9);
}

TEST(Projectile, ErrorHalvesWithTheStep) {
  const Vec3 x0(0.0, 0.0, 0.0), v0(2.0, 5.0, 0.0);
  const double t = 0.8;
  const Vec3 exact = x0 + v0 * t + 0.5 * kGravity * t * t;
  for (ParticleIntegrator integrator : {ParticleIntegrator::ExplicitEuler, ParticleIntegrator::SemiImplicitEuler}) {
    const double coarse = (fly(integrator, 1e-2, 80, x0, v0).position - exact).norm();
    const double fine = (fly(integrator, 5e-3, 160, x0, v0).position - exact).norm();
    EXPECT_NEAR(coarse / fine, 2.0, 1e-6) << particleIntegratorName(integrator);
  }
}

TEST(Drag, LinearDragReachesTerminalVelocityMgOverK) {
  const double m = 0.05, k = 0.2;  // [kg], [N s/m]; time constant m / k = 0.25 s
  World world(particleSettings(1e-3, kGravity));
  ParticleSystemDef def = singleParticle(m, Vec3(0.0, 100.0, 0.0), Vec3(4.0, 0.0, 0.0));
  def.dragLinear = k;
  addParticleSystem(world, def);
  stepN(world, 10000);  // 40 time constants
  const Vec3 v = particleSystems(world)[0].particles().velocity[0];
  const Vec3 terminal = m * kGravity / k;  // 2.4525 m/s down
  EXPECT_NEAR((v - terminal).norm(), 0.0, 1e-9 * terminal.norm());
}

TEST(Drag, QuadraticDragReachesTerminalSpeedSqrtMgOverK) {
  const double m = 0.05, k2 = 0.02;  // [kg], [N s^2/m^2]
  World world(particleSettings(1e-3, kGravity));
  ParticleSystemDef def = singleParticle(m, Vec3::Zero(), Vec3::Zero());
  def.dragQuadratic = k2;
  addParticleSystem(world, def);
  stepN(world, 20000);
  const Vec3 v = particleSystems(world)[0].particles().velocity[0];
  EXPECT_NEAR(v.y(), -std::sqrt(m * kGravity.norm() / k2), 1e-6);
}

TEST(Drag, WindCarriesAParticleAtTheWindSpeed) {
  World world(particleSettings(1e-3, Vec3::Zero()));
  ParticleSystemDef def = singleParticle(0.01, Vec3::Zero(), Vec3::Zero());
  def.dragLinear = 0.1;  // time constant 0.1 s
  def.wind.velocity = Vec3(3.0, 0.0, 1.0);
  addParticleSystem(world, def);
  stepN(world, 3000);
  EXPECT_NEAR((particleSystems(world)[0].particles().velocity[0] - def.wind.velocity).norm(), 0.0, 1e-9);
}

TEST(Attractor, PullsAParticleIntoAnOrbitThatKeepsItsEnergy) {
  // A circular orbit of radius r about a magnet of strength s (softening far below r): v = sqrt(s / (m r)).
  const double m = 1.0, s = 4.0, r = 2.0;
  World world(particleSettings(1e-4, Vec3::Zero()));
  ParticleSystemDef def = singleParticle(m, Vec3(r, 0.0, 0.0), Vec3(0.0, 0.0, std::sqrt(s / (m * r))));
  def.attractors.push_back({Vec3::Zero(), s, 1e-6});
  addParticleSystem(world, def);
  stepN(world, 20000);  // 2 s, about half an orbit (period 2 pi r / v = 8.9 s)
  const Vec3 x = particleSystems(world)[0].particles().position[0];
  EXPECT_NEAR(x.norm(), r, 1e-3);
  EXPECT_GT(std::abs(x.z()), 1.0) << "it moved round, not along a line";
}

}  // namespace
}  // namespace rbsim
