#include "rbsim/particles/particle_forces.h"

#include <cmath>

#include "particles/noise.h"

namespace rbsim {

void addSpringForces(const std::vector<ParticleSpring>& springs, const ParticleStore& store, std::vector<Vec3>& force) {
  for (const ParticleSpring& s : springs) {
    const Vec3 d = store.position[s.b] - store.position[s.a];
    const double length = d.norm();
    if (length == 0.0) continue;  // coincident: no direction to push along
    const Vec3 u = d / length;
    const double magnitude =
        s.stiffness * (length - s.restLength) + s.damping * (store.velocity[s.b] - store.velocity[s.a]).dot(u);
    force[s.a] += magnitude * u;
    force[s.b] -= magnitude * u;
  }
}

void addFlockingForces(const FlockDef& flock, const ParticleStore& store, std::vector<Vec3>& force) {
  const std::size_t n = store.count();
  const double radius2 = flock.radius * flock.radius;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 away = Vec3::Zero(), meanVelocity = Vec3::Zero(), meanPosition = Vec3::Zero();
    int neighbours = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const Vec3 d = store.position[i] - store.position[j];
      const double r2 = d.squaredNorm();
      if (j == i || r2 > radius2 || r2 == 0.0) continue;
      away += d / r2;  // separation: stronger the closer the neighbour
      meanVelocity += store.velocity[j];
      meanPosition += store.position[j];
      ++neighbours;
    }
    if (neighbours == 0) continue;
    meanVelocity /= neighbours;
    meanPosition /= neighbours;
    force[i] += flock.separation * away + flock.alignment * (meanVelocity - store.velocity[i]) +
                flock.cohesion * (meanPosition - store.position[i]);
  }
}

Vec3 windVelocity(const WindDef& wind, const Vec3& x, double t, std::uint64_t seed) {
  if (wind.turbulence == 0.0) return wind.velocity;
  return wind.velocity + wind.turbulence * noiseVector(x / wind.scale, t * wind.frequency, seed);
}

}  // namespace rbsim
