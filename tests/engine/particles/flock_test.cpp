// Reynolds' three rules (particles/particle_forces.h addFlockingForces), each on its own, against
// what it says, and buoyancy (ParticleSystemDef::gravityScale < 0: hot gas rises). With every
// particle within the radius of every other, n particles of mass m and a rule of gain c:
//   cohesion c (mean of the others - x) = c n / (n - 1) (C - x): each particle swings about the
//     centroid C, x - C = (x0 - C) cos(w t), w^2 = c n / ((n - 1) m), all through C at once;
//   alignment a (mean of the others' v - v) = a n / (n - 1) (V - v): v - V decays as
//     exp(-a n t / ((n - 1) m));
//   separation s sum d / |d|^2 pushes every pair apart along d.
// Each rule is pairwise balanced there, so the momentum, and with it C or V, is kept.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "particle_test_util.h"
#include "rbsim/particles/particle_system.h"
#include "rbsim/world/systems.h"

namespace rbsim {
namespace {

constexpr std::size_t kBoids = 40;
constexpr double kMass = 0.5;  // [kg]
constexpr double kFlockDt = 1e-3;   // [s]

// A world of kBoids particles at rest or moving at random in a 2 m cube, all neighbours of each
// other, with only the rules `flock` sets.
World flockWorld(const FlockDef& flock, bool moving) {
  World world(test::particleSettings(kFlockDt, Vec3::Zero()));
  ParticleSystemDef def;
  def.capacity = kBoids;
  def.flock = flock;
  def.flock.enabled = true;
  def.flock.radius = 100.0;
  def.collision.planes = def.collision.bodies = false;
  addParticleSystem(world, def);
  ParticleStore& store = particleSystems(world)[0].particles();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t k = 0; k < kBoids; ++k) {
    const std::size_t i = store.add();
    store.position[i] = Vec3(u(random), u(random), u(random));
    store.velocity[i] = moving ? Vec3(u(random), u(random), u(random)) : Vec3::Zero();
    store.inverseMass[i] = 1.0 / kMass;
    store.lifetime[i] = kImmortal;
  }
  return world;
}

const ParticleStore& boids(const World& world) { return particleSystems(world)[0].particles(); }

Vec3 centroid(const ParticleStore& s) {
  Vec3 c = Vec3::Zero();
  for (std::size_t i = 0; i < s.count(); ++i) c += s.position[i] / static_cast<double>(s.count());
  return c;
}

Vec3 meanVelocity(const ParticleStore& s) { return s.momentum() / (kMass * static_cast<double>(s.count())); }

double positionSpread(const ParticleStore& s) {  // root mean square distance from the centroid [m]
  const Vec3 c = centroid(s);
  double sum = 0.0;
  for (std::size_t i = 0; i < s.count(); ++i) sum += (s.position[i] - c).squaredNorm();
  return std::sqrt(sum / static_cast<double>(s.count()));
}

double velocitySpread(const ParticleStore& s) {
  const Vec3 v = meanVelocity(s);
  double sum = 0.0;
  for (std::size_t i = 0; i < s.count(); ++i) sum += (s.velocity[i] - v).squaredNorm();
  return std::sqrt(sum / static_cast<double>(s.count()));
}

double meanPairDistance(const ParticleStore& s) {
  double sum = 0.0;
  for (std::size_t i = 0; i < s.count(); ++i) {
    for (std::size_t j = i + 1; j < s.count(); ++j) sum += (s.position[i] - s.position[j]).norm();
  }
  return sum / (0.5 * static_cast<double>(s.count() * (s.count() - 1)));
}

TEST(Flock, CohesionSwingsEveryBoidThroughTheCentroidAtOnce) {
  FlockDef flock;
  flock.separation = flock.alignment = 0.0;
  flock.cohesion = 2.0;  // [N/m]
  World world = flockWorld(flock, false);
  const Vec3 c0 = centroid(boids(world));
  const double spread0 = positionSpread(boids(world));
  const double n = kBoids;
  const double omega = std::sqrt(flock.cohesion * n / ((n - 1.0) * kMass));  // [rad/s]
  const int quarter = static_cast<int>(std::lround(0.5 * M_PI / omega / kFlockDt));
  test::stepN(world, quarter);
  EXPECT_LT(positionSpread(boids(world)), 0.01 * spread0) << "a quarter swing: all at the centroid";
  test::stepN(world, quarter);
  EXPECT_NEAR(positionSpread(boids(world)) / spread0, 1.0, 0.01) << "half a swing: as far out, mirrored";
  EXPECT_LT((centroid(boids(world)) - c0).norm(), 1e-12);
}

TEST(Flock, AlignmentDecaysEveryVelocityToTheMeanAtItsRate) {
  FlockDef flock;
  flock.separation = flock.cohesion = 0.0;
  flock.alignment = 0.5;  // [N s/m]
  World world = flockWorld(flock, true);
  const Vec3 v0 = meanVelocity(boids(world));
  const double spread0 = velocitySpread(boids(world));
  const double n = kBoids, t = 1.0;
  test::stepN(world, static_cast<int>(t / kFlockDt));
  const double expected = std::exp(-flock.alignment * n / ((n - 1.0) * kMass) * t);  // 0.358
  EXPECT_NEAR(velocitySpread(boids(world)) / spread0, expected, 0.01 * expected);
  EXPECT_LT((meanVelocity(boids(world)) - v0).norm(), 1e-12) << "the flock's momentum is kept";
}

TEST(Flock, SeparationSpreadsTheFlockAndKeepsItsCentre) {
  FlockDef flock;
  flock.alignment = flock.cohesion = 0.0;
  flock.separation = 0.02;  // [N m]
  World world = flockWorld(flock, false);
  const Vec3 c0 = centroid(boids(world));
  double spacing = meanPairDistance(boids(world));
  for (int second = 0; second < 3; ++second) {
    test::stepN(world, static_cast<int>(1.0 / kFlockDt));
    const double next = meanPairDistance(boids(world));
    EXPECT_GT(next, spacing * 1.01) << "after " << second + 1 << " s";
    spacing = next;
  }
  EXPECT_LT((centroid(boids(world)) - c0).norm(), 1e-12);
  EXPECT_LT(boids(world).momentum().norm(), 1e-12);
}

TEST(Flock, SpeedsStayWithinTheLimits) {
  FlockDef flock;
  flock.minSpeed = 0.5;
  flock.maxSpeed = 0.8;  // [m/s]
  World world = flockWorld(flock, true);
  test::stepN(world, 500);
  for (std::size_t i = 0; i < boids(world).count(); ++i) {
    const double speed = boids(world).velocity[i].norm();
    EXPECT_GE(speed, flock.minSpeed - 1e-12);
    EXPECT_LE(speed, flock.maxSpeed + 1e-12);
  }
}

// Fire and smoke: gravityScale < 0 is hot gas, pushed up by -scale g; > 0 sinks. With linear drag
// k each reaches its terminal velocity m g scale / k, up for hot and down for cool.
TEST(Buoyancy, HotParticlesRiseAndCoolOnesSink) {
  const Vec3 g(0.0, -9.81, 0.0);
  const double m = 0.01, k = 0.05;  // [kg], [N s/m]: time constant 0.2 s
  for (const double scale : {-0.5, 0.3}) {
    World world(test::particleSettings(kFlockDt, g));
    ParticleSystemDef def = test::singleParticle(m, Vec3::Zero(), Vec3::Zero());
    def.gravityScale = scale;
    def.dragLinear = k;
    addParticleSystem(world, def);
    test::stepN(world, 4000);  // 20 time constants
    const Vec3& v = particleSystems(world)[0].particles().velocity[0];
    EXPECT_NEAR(v.y(), m * scale * g.y() / k, 1e-6) << "scale " << scale;
    EXPECT_EQ(v.y() > 0.0, scale < 0.0) << "hot rises, cool sinks";
  }
}

}  // namespace
}  // namespace rbsim
