#include "geometry/triangle_edges.h"

#include <algorithm>
#include <tuple>
#include <utility>

namespace rbsim {

namespace {

Vec3 unitNormal(const std::vector<Vec3>& v, const Triangle& t) {
  const Vec3 n = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

}  // namespace

std::vector<std::uint8_t> activeEdges(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) {
  // Every edge as (lower vertex, higher vertex, triangle, edge slot), sorted so that the sides of
  // one edge are neighbours: n log n, no hash map.
  struct Side {
    std::uint32_t lo, hi, triangle;
    std::uint8_t slot;
  };
  std::vector<Side> sides;
  sides.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (std::uint8_t k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  std::vector<std::uint8_t> active(triangles.size(), kAllEdgesActive);
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i == 2) {  // a manifold edge: its two triangles decide
      const Side& s = sides[i];
      const Side& o = sides[i + 1];
      const Vec3 n = unitNormal(vertices, triangles[s.triangle]);
      const Vec3 m = unitNormal(vertices, triangles[o.triangle]);
      // The other triangle's far vertex below this one's plane: the surface turns away, convex.
      const Vec3& far = vertices[triangles[o.triangle][(o.slot + 2) % 3]];
      const bool convex = n.dot(far - vertices[triangles[s.triangle][0]]) < 0.0;
      if (!convex || n.dot(m) > kFlatEdgeCosine) {
        active[s.triangle] &= static_cast<std::uint8_t>(~(1u << s.slot));
        active[o.triangle] &= static_cast<std::uint8_t>(~(1u << o.slot));
      }
    }
    i = j;
  }
  return active;
}

}  // namespace rbsim
