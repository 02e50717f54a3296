#include "rbsim/particles/particle_collision.h"

namespace rbsim {

bool collideBody(Vec3& x, Vec3& v, const RigidBody& body, const BodySolid& shape, const ParticleCollisionDef& c) {
  const Vec3 arm = x - body.position();
  const double reach = shape.convex.boundingRadius + c.radius;
  if (arm.squaredNorm() > reach * reach) return false;  // before the rotation, which costs more
  const Mat3& R = body.rotation();
  const SurfaceQuery surface = querySurface(shape, R.transpose() * arm);
  const double depth = c.radius - surface.distance;
  if (!(depth > 0.0)) return false;
  const Vec3 normal = R * surface.normal;
  x += depth * normal;
  const Vec3 surfaceVelocity = body.velocity() + body.angularVelocity().cross(x - body.position());
  v = surfaceVelocity + respond(v - surfaceVelocity, normal, c);
  return true;
}

}  // namespace rbsim
