#pragma once
// Particles against planes and rigid bodies: a particle found inside is projected back to the
// surface (so it is never left below a plane), and its velocity relative to the surface loses
// its approach: v_n' = -e v_n (seed 000 "Collision Response", coefficient of restitution), with
// Coulomb friction taking at most mu |dv_n| of the tangential velocity (seed 000 "Friction",
// the kinetic case; a particle whose tangential speed is within the cone sticks). Particles do
// not push back: the coupling is one-way, bodies move particles.
#include <algorithm>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/contact.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/particles/particle_def.h"

namespace rbsim {

// The velocity relative to a surface of normal n after the impact, when it approaches (v.n < 0).
inline Vec3 respond(const Vec3& v, const Vec3& n, const ParticleCollisionDef& c) {
  const double vn = v.dot(n);
  if (vn >= 0.0) return v;  // separating: position correction only
  const Vec3 tangential = v - vn * n;
  const double speed = tangential.norm();
  const double normalChange = (1.0 + c.restitution) * -vn;  // |dv_n|
  const double keep = speed > 0.0 ? std::max(0.0, 1.0 - c.friction * normalChange / speed) : 0.0;
  return keep * tangential - c.restitution * vn * n;
}

// Keeps x at least c.radius above the plane; returns true on contact.
inline bool collidePlane(Vec3& x, Vec3& v, const Plane& plane, const ParticleCollisionDef& c) {
  const double depth = c.radius - plane.signedDistance(x);
  if (!(depth > 0.0)) return false;
  x += depth * plane.normal;
  v = respond(v, plane.normal, c);
  return true;
}

// Keeps x outside the body's solid by c.radius, pushing it out along the surface normal (seed 000
// "Collision Detection": a point in object space tested against the implicit volume); the
// response uses the velocity relative to the body's surface point.
bool collideBody(Vec3& x, Vec3& v, const RigidBody& body, const BodySolid& shape, const ParticleCollisionDef& c);

}  // namespace rbsim
