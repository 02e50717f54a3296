#include "rbsim/world/ray_cast.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "rbsim/collision/shape_queries.h"
#include "rbsim/world/world.h"

namespace rbsim {

namespace {

// Moller and Trumbore, "Fast, minimum storage ray-triangle intersection" (1997): the distance
// along the unit direction, or a negative number when the ray misses or the triangle faces away.
double rayTriangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = direction.cross(e2);
  const double det = e1.dot(p);
  if (det <= 0.0) return -1.0;  // back face or edge-on: the ray enters through front faces
  const Vec3 s = origin - a;
  const double u = s.dot(p) / det;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Vec3 q = s.cross(e1);
  const double v = direction.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return e2.dot(q) / det;
}

std::optional<WorldRayHit> meshHit(const RigidBody& body, const Vec3& origin, const Vec3& direction, double maxDistance) {
  std::optional<WorldRayHit> best;
  const std::vector<Vec3>& vertices = body.worldVertices();
  for (const Triangle& t : body.mesh().triangles) {
    const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const double s = rayTriangle(origin, direction, a, b, c);
    if (s >= 0.0 && s <= maxDistance && (!best || s < best->distance)) {
      WorldRayHit hit;
      hit.distance = s;
      hit.normal = (b - a).cross(c - a).normalized();
      best = hit;
    }
  }
  return best;
}

}  // namespace

std::optional<WorldRayHit> rayCast(const World& world, const Vec3& origin, const Vec3& direction, double maxDistance) {
  // stableNorm, not norm: sqrt of the squared norm is 0 below 1e-154 and inf above 1e154, and a
  // direction of any finite length is a direction (issue 56).
  const double length = direction.stableNorm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::invalid_argument("rayCast: expected a non-zero, finite direction");
  }
  if (!origin.allFinite()) throw std::invalid_argument("rayCast: expected a finite origin");
  if (!(maxDistance >= 0.0)) throw std::invalid_argument("rayCast: expected a max distance >= 0");
  const Vec3 d = direction / length;
  std::optional<WorldRayHit> best;
  double reach = maxDistance;  // shrinks to the nearest hit so far
  const auto keep = [&](WorldRayHit hit) {
    hit.point = origin + hit.distance * d;
    reach = hit.distance;
    best = hit;
  };
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const RigidBody& body = world.bodies()[i];
    std::optional<WorldRayHit> hit;
    if (body.isCompound()) {
      // Each child in its own frame, the nearest hit of them.
      for (const ChildShape& child : body.children()) {
        const Mat3 R = body.rotation() * child.orientation.toRotationMatrix();
        const Vec3 localOrigin = R.transpose() * (origin - body.bodyToWorld(child.position));
        const double limit = hit ? hit->distance : reach;
        if (const std::optional<RayHit> local = rbsim::rayCast(child.shape, localOrigin, R.transpose() * d, limit)) {
          hit = WorldRayHit{};
          hit->distance = local->fraction;
          hit->normal = R * local->normal;
        }
      }
    } else if (body.shape().type == ShapeType::Mesh) {
      hit = meshHit(body, origin, d, reach);
    } else {
      // In the body's frame, p_local = R^T (p - x) (seed 004's p' = R p + x, inverted).
      const Mat3& R = body.rotation();
      const Vec3 localOrigin = R.transpose() * (origin - body.position());
      if (const std::optional<RayHit> local = rbsim::rayCast(body.shape(), localOrigin, R.transpose() * d, reach)) {
        hit = WorldRayHit{};
        hit->distance = local->fraction;  // a unit direction: the fraction is the distance
        hit->normal = R * local->normal;
      }
    }
    if (hit && hit->distance <= reach) {
      hit->body = world.idAt(i);
      keep(*hit);
    }
  }
  for (std::size_t k = 0; k < world.planes().size(); ++k) {
    const Plane& plane = world.planes()[k];
    // Inside the half-space behind the plane, as inside a body: a hit at 0.
    const double s = plane.signedDistance(origin) < 0.0 ? 0.0 : plane.rayHit(origin, d);
    if (std::isfinite(s) && s <= reach) {  // rayHit says a miss with infinity, which an unbounded reach admits
      WorldRayHit hit;
      hit.isPlane = true;
      hit.plane = k;
      hit.distance = s;
      hit.normal = plane.normal;
      keep(hit);
    }
  }
  return best;
}

}  // namespace rbsim
