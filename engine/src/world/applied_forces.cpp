// The forces of scripts and springs on a body at its pose now (world/scripts.h, world/spring.h).
#include "rbsim/world/scripts.h"
#include "rbsim/world/spring.h"

namespace rbsim {

std::pair<Vec3, Vec3> inWorldFrame(const ScriptedForce& f, const RigidBody& body) {
  const Vec3 point = f.pointFrame == Frame::Body ? body.bodyToWorld(f.point) : f.point;
  const Vec3 force = f.forceFrame == Frame::Body ? Vec3(body.rotation() * f.force) : f.force;
  return {point, force};
}

std::pair<Vec3, Vec3> forceOfSpring(const Spring& spring, const RigidBody& body) {
  const Vec3 point = body.bodyToWorld(spring.point);
  const Vec3 d = point - spring.anchor;
  const double length = d.norm();
  if (length == 0.0) return {point, Vec3::Zero()};
  const Vec3 u = d / length;
  const Vec3 pointVelocity = body.velocity() + body.angularVelocity().cross(point - body.position());
  const double magnitude = spring.stiffness * (length - spring.restLength) + spring.damping * pointVelocity.dot(u);
  return {point, -magnitude * u};
}

}  // namespace rbsim
