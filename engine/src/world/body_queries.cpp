// One body's or plane's answer to a ray and to a closest-point query (world/body_queries.h).
#include "world/body_queries.h"

#include <cmath>
#include <limits>

#include "geometry/distance.h"
#include "rbsim/collision/shape_queries.h"

namespace rbsim {

namespace {

// Moller and Trumbore, "Fast, minimum storage ray-triangle intersection" (1997): the distance
// along the unit direction, or a negative number when the ray misses or the triangle faces away.
double rayFrontTriangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b, const Vec3& c) {
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

// Calls f(shape, R, x, child) for each shape of the body the filter lets through, world pose.
template <typename F>
void forEachQueryShape(const RigidBody& body, const QueryFilter& filter, F f) {
  if (!body.isCompound()) {
    if (passes(body.filter(), filter)) f(body.shape(), body.rotation(), body.position(), -1);
    return;
  }
  for (std::size_t k = 0; k < body.children().size(); ++k) {
    const ChildShape& child = body.children()[k];
    if (!passes(child.filter, filter)) continue;
    f(child.shape, Mat3(body.rotation() * child.orientation.toRotationMatrix()), body.bodyToWorld(child.position),
      static_cast<int>(k));
  }
}

}  // namespace

bool anyShapePasses(const RigidBody& body, const QueryFilter& filter) {
  if (!body.isCompound()) return passes(body.filter(), filter);
  for (const ChildShape& child : body.children()) {
    if (passes(child.filter, filter)) return true;
  }
  return false;
}

std::optional<QueryHit> rayBody(const RigidBody& body, const Vec3& origin, const Vec3& d, double reach,
                                const QueryFilter& filter) {
  std::optional<QueryHit> best;
  if (!body.isCompound() && body.shape().type == ShapeType::Mesh) {
    if (!passes(body.filter(), filter)) return best;
    const std::vector<Vec3>& vertices = body.worldVertices();
    for (const Triangle& t : body.mesh().triangles) {
      const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
      const double s = rayFrontTriangle(origin, d, a, b, c);
      if (s >= 0.0 && s <= reach && (!best || s < best->distance)) {
        best = QueryHit{};
        best->distance = s;
        best->normal = (b - a).cross(c - a).normalized();
      }
    }
  } else {
    forEachQueryShape(body, filter, [&](const Shape& shape, const Mat3& R, const Vec3& x, int child) {
      // In the shape's frame, p_local = R^T (p - x) (seed 004's p' = R p + x, inverted); a unit
      // direction, so the fraction is the distance.
      const double limit = best ? best->distance : reach;
      if (const std::optional<RayHit> local = rayCast(shape, R.transpose() * (origin - x), R.transpose() * d, limit)) {
        best = QueryHit{};
        best->distance = local->fraction;
        best->normal = R * local->normal;
        best->child = child;
      }
    });
  }
  if (best) best->point = origin + best->distance * d;
  return best;
}

std::optional<QueryHit> rayPlane(const Plane& plane, const Vec3& origin, const Vec3& d, double reach) {
  // Inside the half-space behind the plane, as inside a body: a hit at 0.
  const double s = plane.signedDistance(origin) < 0.0 ? 0.0 : plane.rayHit(origin, d);
  if (!std::isfinite(s) || s > reach) return std::nullopt;  // rayHit says a miss with infinity
  QueryHit hit;
  hit.isPlane = true;
  hit.distance = s;
  hit.point = origin + s * d;
  hit.normal = plane.normal;
  return hit;
}

std::optional<QueryHit> closestOnBody(const RigidBody& body, const Vec3& p, const QueryFilter& filter) {
  std::optional<QueryHit> best;
  const auto keep = [&](double distance, const Vec3& point, const Vec3& normal, int child) {
    if (best && distance >= best->distance) return;
    best = QueryHit{};
    best->distance = distance;
    best->point = point;
    best->normal = normal;
    best->child = child;
  };
  if (!body.isCompound() && body.shape().type == ShapeType::Mesh) {
    if (!passes(body.filter(), filter)) return best;
    const std::vector<Vec3>& vertices = body.worldVertices();
    for (const Triangle& t : body.mesh().triangles) {
      const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
      const PointTriangleResult near = closestPointOnTriangle(p, a, b, c);
      const Vec3& q = near.closest;
      const double distance = near.distance;
      // On the surface itself, the face's normal; elsewhere the way from the surface to p.
      const Vec3 normal = distance > 0.0 ? Vec3((p - q) / distance) : Vec3((b - a).cross(c - a).normalized());
      keep(distance, q, normal, -1);
    }
    return best;
  }
  forEachQueryShape(body, filter, [&](const Shape& shape, const Mat3& R, const Vec3& x, int child) {
    const ShapeDistance local = signedDistance(shape, R.transpose() * (p - x));
    const Vec3 normal = R * local.normal;
    // Exact signed distances: the nearest surface point lies -distance along the normal from p.
    keep(local.distance, p - local.distance * normal, normal, child);
  });
  return best;
}

QueryHit closestOnPlane(const Plane& plane, const Vec3& p) {
  QueryHit hit;
  hit.isPlane = true;
  hit.distance = plane.signedDistance(p);
  hit.point = p - hit.distance * plane.normal;
  hit.normal = plane.normal;
  return hit;
}

}  // namespace rbsim
