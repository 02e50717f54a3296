#include "collision/narrowphase/shape_triangle.h"

#include <cmath>

#include "collision/narrowphase/convex_convex.h"
#include "geometry/distance.h"
#include "geometry/triangle_edges.h"

namespace rbsim {

namespace {

// A sphere centre nearer its closest triangle point than this [m] gives no direction: it takes
// the face normal (the centre is then inside the triangle, pushed out to the front).
constexpr double kCentreOnPlane = 1e-12;

// A sphere against a triangle: the closest point q of the triangle to the centre c, n = (c - q)
// / |c - q|, depth r - |c - q| (Ericson 5.1.5). A centre on the triangle's plane itself takes the
// face normal.
ContactManifold sphereTriangle(const Vec3& centre, double radius, const WorldTriangle& t, double margin) {
  ContactManifold m;
  const PointTriangleResult q = closestPointOnTriangle(centre, t.vertices[0], t.vertices[1], t.vertices[2]);
  const double depth = radius - q.distance;
  if (depth < -margin) return m;
  m.normal = q.distance > kCentreOnPlane ? Vec3((centre - q.closest) / q.distance) : t.normal;
  m.add(q.closest + 0.5 * (centre - radius * m.normal - q.closest), depth);
  return m;
}

// Whether the triangle's point p lies on one of its active edges (within the tolerance).
bool onActiveEdge(const WorldTriangle& t, const Vec3& p) {
  for (int k = 0; k < 3; ++k) {
    if (!(t.activeEdges & (1u << k))) continue;
    const Vec3& a = t.vertices[k];
    const Vec3 edge = t.vertices[(k + 1) % 3] - a;
    const double length = edge.norm();
    if (length > 0.0 && (p - a).cross(edge).norm() / length < kTriangleFeatureTolerance) return true;
  }
  return false;
}

}  // namespace

void shapePointsOf(const PosedShape& s, ShapePoints& out) {
  out.points.clear();
  const Shape& shape = *s.shape;
  out.radius = shape.isRound() ? shape.radius : 0.0;
  switch (shape.type) {
    case ShapeType::Sphere: out.points.push_back(s.position); return;
    case ShapeType::Capsule: {
      const auto [lo, hi] = shape.segment();
      out.points.push_back(s.rotation * lo + s.position);
      out.points.push_back(s.rotation * hi + s.position);
      return;
    }
    case ShapeType::Box:
    case ShapeType::RoundedBox:
      for (int i = 0; i < 8; ++i) {
        const Vec3& h = shape.halfExtents;
        const Vec3 corner((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
        out.points.push_back(s.rotation * corner + s.position);
      }
      return;
    case ShapeType::ConvexHull:
    case ShapeType::Mesh:  // without a grid a mesh is its hull
      for (const Vec3& v : shape.hull->vertices) out.points.push_back(s.rotation * v + s.position);
      return;
  }
}

void removeInternalEdgeNormal(const WorldTriangle& t, const Vec3& centre, double radius, double margin,
                              ContactManifold& m) {
  if (m.count == 0 || m.normal.dot(t.normal) > kFlatEdgeCosine) return;
  // A body behind the triangle is not resting on it: its contact is left as it is.
  if (t.normal.dot(centre - t.vertices[0]) <= 0.0) return;
  for (int i = 0; i < m.count; ++i) {
    const ContactPoint& p = m.points[i];
    if (onActiveEdge(t, p.position + 0.5 * p.depth * m.normal)) return;  // a real edge or corner
  }
  // Each point again along the face normal: the shape's point, moved from its core along n to
  // along the face normal, and its depth below the triangle's plane.
  const Vec3 n = m.normal;
  ContactManifold face;
  face.normal = t.normal;
  for (int i = 0; i < m.count; ++i) {
    const ContactPoint& p = m.points[i];
    const Vec3 core = p.position - 0.5 * p.depth * n + radius * n;
    const Vec3 onShape = core - radius * t.normal;
    const double depth = -t.normal.dot(onShape - t.vertices[0]);
    if (depth >= -margin) face.add(onShape + 0.5 * depth * t.normal, depth);
  }
  m = face;
}

ContactManifold collideShapeTriangle(const PosedShape& shape, const ShapePoints& points, const WorldTriangle& t,
                                     double margin) {
  ContactManifold m;
  if (shape.shape->type == ShapeType::Sphere) {
    m = sphereTriangle(shape.position, points.radius, t, margin);
  } else {
    thread_local std::vector<Vec3> corners(3);
    corners.assign(t.vertices.begin(), t.vertices.end());
    const double r = points.radius;
    const ConvexContact c = collideConvex(corners, points.points, margin + r);
    m.normal = c.manifold.normal;
    // A round shape's surface is r beyond its core: each point's depth grows by r and moves to
    // midway between the triangle and that surface (as shape_pairs.cpp's roundBoxCores).
    for (int i = 0; i < c.manifold.count; ++i) {
      const ContactPoint& p = c.manifold.points[i];
      if (p.depth + r >= -margin) m.add(p.position - 0.5 * r * m.normal, p.depth + r);
    }
  }
  removeInternalEdgeNormal(t, shape.position, points.radius, margin, m);
  return m;
}

}  // namespace rbsim
