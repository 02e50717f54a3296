#include "collision/narrowphase/triangle_triangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "geometry/distance.h"

namespace rbsim {

namespace {

using Tri = std::array<Vec3, 3>;

// The two points where a triangle's edges cross the other plane, given the vertices' signed
// distances d to it: Moller's compute_intervals picks the vertex alone on its side, and the
// crossings lie on its two edges. Returns false when all three distances are zero (coplanar).
bool crossingPoints(const Tri& v, const std::array<double, 3>& d, Vec3& p, Vec3& q) {
  int lone;
  if (d[0] * d[1] > 0.0) lone = 2;
  else if (d[0] * d[2] > 0.0) lone = 1;
  else if (d[1] * d[2] > 0.0 || d[0] != 0.0) lone = 0;
  else if (d[1] != 0.0) lone = 1;
  else if (d[2] != 0.0) lone = 2;
  else return false;
  const int i = (lone + 1) % 3, j = (lone + 2) % 3;
  // Each case above makes d[lone] - d[i] and d[lone] - d[j] non-zero.
  p = v[lone] + (v[i] - v[lone]) * (d[lone] / (d[lone] - d[i]));
  q = v[lone] + (v[j] - v[lone]) * (d[lone] / (d[lone] - d[j]));
  return true;
}

// Signed distances of v to the plane of t (unit normal n), snapped to 0 within tol.
std::array<double, 3> planeDistances(const Tri& v, const Vec3& n, const Vec3& origin, double tol) {
  std::array<double, 3> d;
  for (int k = 0; k < 3; ++k) {
    d[k] = n.dot(v[k] - origin);
    if (std::abs(d[k]) <= tol) d[k] = 0.0;
  }
  return d;
}

bool sameSideStrict(const std::array<double, 3>& d) {
  return (d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0) || (d[0] < 0.0 && d[1] < 0.0 && d[2] < 0.0);
}

using Vec2 = Eigen::Vector2d;

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool onSegment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Closed 2D segments ab and cd intersect.
bool segmentsIntersect2d(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
         (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

bool pointInTriangle2d(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double o1 = orient(a, b, p), o2 = orient(b, c, p), o3 = orient(c, a, p);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

// Moller §3 coplanar case: project onto the axis plane where the triangles have the largest
// area (dropping the normal's largest component), then any edge-edge crossing or one triangle containing a vertex of the other.
bool coplanarIntersect(const Tri& a, const Tri& b, const Vec3& normal) {
  int drop;
  normal.cwiseAbs().maxCoeff(&drop);
  const int i0 = (drop + 1) % 3, i1 = (drop + 2) % 3;
  std::array<Vec2, 3> p, q;
  for (int k = 0; k < 3; ++k) {
    p[k] = Vec2(a[k][i0], a[k][i1]);
    q[k] = Vec2(b[k][i0], b[k][i1]);
  }
  for (int e = 0; e < 3; ++e) {
    for (int f = 0; f < 3; ++f) {
      if (segmentsIntersect2d(p[e], p[(e + 1) % 3], q[f], q[(f + 1) % 3])) return true;
    }
  }
  return pointInTriangle2d(p[0], q[0], q[1], q[2]) || pointInTriangle2d(q[0], p[0], p[1], p[2]);
}

double longestEdge2(const Tri& t) {
  return std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[1]).squaredNorm(), (t[0] - t[2]).squaredNorm()});
}

// The longest edge of a zero-area triangle: the segment it degenerates to.
std::pair<Vec3, Vec3> longestEdge(const Tri& t) {
  int best = 0;
  for (int e = 1; e < 3; ++e) {
    if ((t[(e + 1) % 3] - t[e]).squaredNorm() > (t[(best + 1) % 3] - t[best]).squaredNorm()) best = e;
  }
  return {t[best], t[(best + 1) % 3]};
}

// Closed segment pq meets the (non-degenerate) triangle t within tol: if pq crosses t's plane
// the crossing point must lie on t; otherwise the nearest pair involves an end of pq or an edge.
bool segmentMeetsTriangle(const Vec3& p, const Vec3& q, const Tri& t, double tol) {
  const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
  const double dp = n.dot(p - t[0]), dq = n.dot(q - t[0]);
  if ((dp > tol && dq < -tol) || (dp < -tol && dq > tol)) {
    const Vec3 x = p + (q - p) * (dp / (dp - dq));
    return closestPointOnTriangle(x, t[0], t[1], t[2]).distance <= tol;
  }
  if (closestPointOnTriangle(p, t[0], t[1], t[2]).distance <= tol) return true;
  if (closestPointOnTriangle(q, t[0], t[1], t[2]).distance <= tol) return true;
  for (int e = 0; e < 3; ++e) {
    if (closestPointsSegmentSegment(p, q, t[e], t[(e + 1) % 3]).distance <= tol) return true;
  }
  return false;
}

}  // namespace

TriTriResult triangleTriangleIntersection(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                          const Vec3& b0, const Vec3& b1, const Vec3& b2) {
  const Tri a = {a0, a1, a2}, b = {b0, b1, b2};
  double longest2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    longest2 = std::max({longest2, (a[(k + 1) % 3] - a[k]).squaredNorm(), (b[(k + 1) % 3] - b[k]).squaredNorm()});
  }
  const double tol = kTriTriPlaneRelTolerance * std::sqrt(longest2);
  const Vec3 na = (a1 - a0).cross(a2 - a0), nb = (b1 - b0).cross(b2 - b0);
  const double longestA2 = longestEdge2(a), longestB2 = longestEdge2(b);
  const bool flatA = na.norm() <= kDegenerateTriangleRatio * longestA2;
  const bool flatB = nb.norm() <= kDegenerateTriangleRatio * longestB2;

  TriTriResult out;
  if (flatA || flatB) {
    out.degenerate = true;
    const auto [p, q] = longestEdge(flatA ? a : b);
    if (flatA && flatB) {
      const auto [r, s] = longestEdge(b);
      out.intersect = closestPointsSegmentSegment(p, q, r, s).distance <= tol;
    } else {
      out.intersect = segmentMeetsTriangle(p, q, flatA ? b : a, tol);
    }
    return out;
  }

  // Steps 1-2: reject if a lies strictly on one side of b's plane; steps 3-4 the other way round.
  const Vec3 unitA = na.normalized(), unitB = nb.normalized();
  const std::array<double, 3> da = planeDistances(a, unitB, b0, tol * longestB2 / nb.norm());
  if (sameSideStrict(da)) return out;
  const std::array<double, 3> db = planeDistances(b, unitA, a0, tol * longestA2 / na.norm());
  if (sameSideStrict(db)) return out;

  // Step 5: the intersection line L = O + t D; parameters by the largest component of D.
  Vec3 pa, qa, pb, qb;
  if (!crossingPoints(a, da, pa, qa) || !crossingPoints(b, db, pb, qb)) {
    out.coplanar = true;
    // Project along the better determined of the two normals.
    const bool aBetter = na.norm() / longestA2 >= nb.norm() / longestB2;
    out.intersect = coplanarIntersect(a, b, aBetter ? unitA : unitB);
    return out;
  }
  int axis;
  unitA.cross(unitB).cwiseAbs().maxCoeff(&axis);
  // Steps 6-7: each triangle's interval on L, then their overlap (closed).
  if (pa[axis] > qa[axis]) std::swap(pa, qa);
  if (pb[axis] > qb[axis]) std::swap(pb, qb);
  if (qa[axis] < pb[axis] || qb[axis] < pa[axis]) return out;
  out.intersect = true;
  out.hasSegment = true;
  out.segment[0] = pa[axis] > pb[axis] ? pa : pb;
  out.segment[1] = qa[axis] < qb[axis] ? qa : qb;
  return out;
}

}  // namespace rbsim
