#pragma once
// Worlds with one particle system for the particle suites: no rigid bodies unless a test adds
// them, collisions and sleeping as each test needs.
#include <cstddef>

#include "rbsim/particles/particle_def.h"
#include "rbsim/world/world.h"

namespace rbsim::test {

inline Settings particleSettings(double dt, const Vec3& gravity) {
  Settings settings;
  settings.timeStep = dt;
  settings.gravity = gravity;
  return settings;
}

// One particle of mass m at x0 with velocity v0, held by nothing but the system's forces.
inline ParticleSystemDef singleParticle(double mass, const Vec3& x0, const Vec3& v0) {
  ParticleSystemDef def;
  def.capacity = 1;
  EmitterDef e;
  e.shape = EmitterShape::Point;
  e.position = x0;
  e.direction = v0.norm() > 0.0 ? Vec3(v0.normalized()) : Vec3::UnitY();
  e.spreadDegrees = 0.0;
  e.speedMin = e.speedMax = v0.norm();
  e.massMin = e.massMax = mass;
  e.rate = 0.0;
  e.burst = 1;
  def.emitters.push_back(e);
  def.collision.planes = false;
  def.collision.bodies = false;
  return def;
}

inline void stepN(World& world, int n) {
  for (int i = 0; i < n; ++i) world.step();
}

}  // namespace rbsim::test
