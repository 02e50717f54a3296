#include "particles/particle_collision.h"

#include <cmath>
#include <limits>

namespace rbsim {

namespace {
// Faces whose normals and offsets agree this closely are one plane (a box face's two triangles).
constexpr double kSamePlaneTolerance = 1e-9;  // [1] and [m]
}  // namespace

ConvexShape convexShapeOf(const Mesh& mesh) {
  ConvexShape shape;
  for (const Vec3& p : mesh.vertices) shape.boundingRadius = std::max(shape.boundingRadius, p.norm());
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    if (!(n.norm() > 0.0)) continue;  // degenerate: no plane
    const Vec3 unit = n.normalized();
    const double offset = unit.dot(a);
    bool known = false;
    for (std::size_t f = 0; f < shape.normals.size() && !known; ++f) {
      known = (shape.normals[f] - unit).norm() < kSamePlaneTolerance &&
              std::abs(shape.offsets[f] - offset) < kSamePlaneTolerance;
    }
    if (!known) {
      shape.normals.push_back(unit);
      shape.offsets.push_back(offset);
    }
  }
  return shape;
}

bool collideBody(Vec3& x, Vec3& v, const RigidBody& body, const ConvexShape& shape, const ParticleCollisionDef& c) {
  const Vec3 arm = x - body.position();
  const double reach = shape.boundingRadius + c.radius;
  if (arm.squaredNorm() > reach * reach || shape.normals.empty()) return false;
  const Mat3& R = body.rotation();
  const Vec3 local = R.transpose() * arm;
  // The signed distance to the convex set is at least the largest face distance; inside, it is
  // exactly that, and the face it belongs to is the nearest way out.
  double largest = -std::numeric_limits<double>::infinity();
  std::size_t face = 0;
  for (std::size_t f = 0; f < shape.normals.size(); ++f) {
    const double d = shape.normals[f].dot(local) - shape.offsets[f];
    if (d > largest) {
      largest = d;
      face = f;
    }
  }
  const double depth = c.radius - largest;
  if (!(depth > 0.0)) return false;
  const Vec3 normal = R * shape.normals[face];
  x += depth * normal;
  const Vec3 surfaceVelocity = body.velocity() + body.angularVelocity().cross(x - body.position());
  v = surfaceVelocity + respond(v - surfaceVelocity, normal, c);
  return true;
}

}  // namespace rbsim
