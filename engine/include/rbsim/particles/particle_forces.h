#pragma once
// Forces on particles, F = ma (seed 000's homework "a particle system based on F = ma"). Field
// forces depend on one particle (drag in wind, magnets) and are evaluated inside the step's
// single pass; pair forces (springs, flocking) are accumulated first into a force array.
#include <cstdint>
#include <vector>

#include "rbsim/math/types.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/particles/particle_store.h"

namespace rbsim {

// A damped spring between particles a and b (seed 000 "particle systems": springs, cloth):
// F_a = (k (|d| - L0) + c (v_b - v_a) . u) u with d = x_b - x_a, u = d / |d|; F_b = -F_a, so
// springs alone conserve linear momentum.
struct ParticleSpring {
  std::uint32_t a = 0, b = 0;
  double restLength = 0.0;  // L0 [m]
  double stiffness = 0.0;   // k [N/m]
  double damping = 0.0;     // c [N s/m]
};

void addSpringForces(const std::vector<ParticleSpring>& springs, const ParticleStore& store, std::vector<Vec3>& force);

// Reynolds, "Flocks, herds and schools: a distributed behavioral model", SIGGRAPH 1987: every
// pair within flock.radius of each other (all pairs tested: flocks are hundreds of particles).
void addFlockingForces(const FlockDef& flock, const ParticleStore& store, std::vector<Vec3>& force);

// Air velocity w(x, t) of the wind field.
Vec3 windVelocity(const WindDef& wind, const Vec3& x, double t, std::uint64_t seed);

// Drag F = -k1 u - k2 |u| u of the velocity u = v - w relative to the air.
inline Vec3 dragForce(const Vec3& relativeVelocity, double k1, double k2) {
  return -(k1 + k2 * relativeVelocity.norm()) * relativeVelocity;
}

// Softened inverse-square magnet (AttractorDef).
inline Vec3 attractorForce(const AttractorDef& a, const Vec3& x) {
  const Vec3 d = a.position - x;
  const double r2 = d.squaredNorm() + a.softening * a.softening;
  return a.strength / (r2 * std::sqrt(r2)) * d;
}

}  // namespace rbsim
