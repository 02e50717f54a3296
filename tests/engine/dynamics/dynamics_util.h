#pragma once
// Worlds for the contact-response suites: a ground plane, boxes, and the quantities the
// assertions read (momenta about the origin, kinetic energy, the lowest vertex).
#include <algorithm>
#include <limits>

#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim::test {

inline Vec3 totalLinearMomentum(const World& world) {
  Vec3 sum = Vec3::Zero();
  for (const RigidBody& b : world.bodies()) sum += b.state().linearMomentum;
  return sum;
}

// Sum over bodies of x x P + L: angular momentum about the world origin.
inline Vec3 totalAngularMomentum(const World& world) {
  Vec3 sum = Vec3::Zero();
  for (const RigidBody& b : world.bodies()) sum += b.position().cross(b.state().linearMomentum) + b.state().angularMomentum;
  return sum;
}

inline double totalKineticEnergy(const World& world) {
  double sum = 0.0;
  for (const RigidBody& b : world.bodies()) sum += b.kineticEnergy();
  return sum;
}

inline double lowestVertexHeight(const RigidBody& body) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : body.worldVertices()) lowest = std::min(lowest, p.y());
  return lowest;
}

inline BodyDef boxWith(const Vec3& extents, double mass, const Vec3& position, const Material& material,
                       const std::string& name) {
  BodyDef def = boxDef(extents, mass, name);
  def.position = position;
  def.material = material;
  def.shape = Shape::box(0.5 * extents);
  return def;
}

}  // namespace rbsim::test
