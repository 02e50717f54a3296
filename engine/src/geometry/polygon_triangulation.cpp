#include "geometry/polygon_triangulation.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rbsim {

namespace {

using Point2 = std::array<double, 2>;

// Twice the signed area of (a, b, c): > 0 when they turn counter-clockwise.
double turn(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// p inside the counter-clockwise triangle (a, b, c) or on its boundary: such a corner would make
// the ear's diagonal cross or touch the rest of the polygon.
bool insideOrOn(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

// Closed segments [a, b] and [c, d] share a point (crossing, touching or overlapping).
bool segmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double abc = turn(a, b, c), abd = turn(a, b, d), cda = turn(c, d, a), cdb = turn(c, d, b);
  const auto within = [](const Point2& p, const Point2& q, const Point2& r) {  // r on the box of pq
    return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
           std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
  };
  if (((abc > 0.0 && abd < 0.0) || (abc < 0.0 && abd > 0.0)) &&
      ((cda > 0.0 && cdb < 0.0) || (cda < 0.0 && cdb > 0.0))) {
    return true;
  }
  return (abc == 0.0 && within(a, b, c)) || (abd == 0.0 && within(a, b, d)) ||
         (cda == 0.0 && within(c, d, a)) || (cdb == 0.0 && within(c, d, b));
}

// Ear clipping presumes a simple polygon: no two edges that are not neighbours may meet.
bool isSimple(const std::vector<Point2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the closing edge neighbours the first
      if (segmentsMeet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  }
  return true;
}

}  // namespace

bool triangulatePolygon(const std::vector<Vec3>& vertices, const std::vector<std::uint32_t>& corners,
                        std::vector<Triangle>& out) {
  const std::size_t n = corners.size();
  if (n < 3) return false;
  // Newell's normal: robust for non-planar and non-convex polygons, zero when there is no area.
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = vertices[corners[i]];
    const Vec3& q = vertices[corners[(i + 1) % n]];
    normal += Vec3((p.y() - q.y()) * (p.z() + q.z()), (p.z() - q.z()) * (p.x() + q.x()),
                   (p.x() - q.x()) * (p.y() + q.y()));
  }
  if (!(normal.norm() > 0.0) || !normal.allFinite()) return false;
  if (n == 3) {
    out.push_back({corners[0], corners[1], corners[2]});
    return true;
  }
  // Project on the coordinate plane most nearly parallel to the polygon, axes ordered so that the
  // polygon runs counter-clockwise there.
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  int u = (drop + 1) % 3, v = (drop + 2) % 3;
  if (normal[drop] < 0.0) std::swap(u, v);
  std::vector<Point2> flat(n);
  for (std::size_t i = 0; i < n; ++i) flat[i] = {vertices[corners[i]][u], vertices[corners[i]][v]};
  if (!isSimple(flat)) return false;

  std::vector<std::size_t> remaining(n);
  for (std::size_t i = 0; i < n; ++i) remaining[i] = i;
  std::vector<Triangle> triangles;
  std::size_t misses = 0;  // consecutive corners that were not ears
  std::size_t i = 0;
  while (remaining.size() > 3) {
    const std::size_t m = remaining.size();
    if (misses >= m) return false;  // a full turn without an ear: only rounding can do this
    const std::size_t prev = remaining[(i + m - 1) % m], here = remaining[i % m], next = remaining[(i + 1) % m];
    bool ear = turn(flat[prev], flat[here], flat[next]) > 0.0;
    for (std::size_t k = 0; ear && k < m; ++k) {
      const std::size_t other = remaining[k];
      if (other == prev || other == here || other == next) continue;
      const Point2& p = flat[other];
      ear = !insideOrOn(p, flat[prev], flat[here], flat[next]);
    }
    if (!ear) {
      ++misses;
      i = (i + 1) % m;
      continue;
    }
    triangles.push_back({corners[prev], corners[here], corners[next]});
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i % m));
    misses = 0;
    i = i % remaining.size();
  }
  triangles.push_back({corners[remaining[0]], corners[remaining[1]], corners[remaining[2]]});
  out.insert(out.end(), triangles.begin(), triangles.end());
  return true;
}

}  // namespace rbsim
