#pragma once
// Emitters: where particles are born and with what initial conditions (seed 000's homework:
// a particle system's sources). Every random draw comes from the system's seeded generator, in a
// fixed order, so a scene gives the same particles on every run.
#include <cstddef>
#include <vector>

#include "body/rigid_body.h"
#include "math/uniform_random.h"
#include "particles/particle_def.h"
#include "particles/particle_store.h"

namespace rbsim {

class Emitter {
 public:
  // `bodies` gives the mesh-surface emitter its body's triangles (their areas, for sampling).
  Emitter(const EmitterDef& def, const std::vector<RigidBody>& bodies);

  // Emits what is due during the step [t, t + dt): the burst when the emitter starts, and
  // rate dt particles, the fraction carried to the next step. Returns the particles that found
  // no free slot (the store was full).
  std::size_t emit(double t, double dt, ParticleStore& store, UniformRandom& random,
                   const std::vector<RigidBody>& bodies);

  const EmitterDef& def() const { return def_; }

 private:
  // Birth position and launch axis (unit), and the velocity of the surface the particle leaves.
  void samplePlace(UniformRandom& random, const std::vector<RigidBody>& bodies, Vec3& position, Vec3& axis,
                   Vec3& surfaceVelocity) const;
  void spawn(std::size_t i, ParticleStore& store, UniformRandom& random, const std::vector<RigidBody>& bodies) const;

  EmitterDef def_;
  double pending_ = 0.0;        // particles due but not yet emitted, < 1 after each step
  bool burstDone_ = false;
  std::vector<double> cumulativeArea_;  // mesh surface: running sum of triangle areas [m^2]
};

// A unit vector uniform over the cone of half-angle `spread` [rad] around the unit `axis`
// (cos theta uniform in [cos spread, 1], which is uniform over the spherical cap's area).
Vec3 sampleCone(const Vec3& axis, double spread, UniformRandom& random);

}  // namespace rbsim
