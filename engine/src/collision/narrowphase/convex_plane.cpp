#include "collision/narrowphase/convex_plane.h"

#include <algorithm>
#include <limits>

#include "collision/narrowphase/manifold_reduction.h"

namespace rbsim {

namespace {

// Keeps the candidates on the outline of their projection onto the plane (Andrew's monotone
// chain, 1979), and the deepest one if it lies deeper than every outline point by more than the
// reduction's tolerance: the reduction only ever picks the deepest point and points that extend
// the outline, and the shadow test below is quadratic in what is left.
void keepOutline(std::vector<ContactPoint>& candidates, const Vec3& normal) {
  const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
  struct Projected {
    double x, y;
    std::size_t index;
  };
  thread_local std::vector<Projected> points, hull;
  points.clear();
  hull.clear();
  std::size_t deepest = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    points.push_back({u.dot(candidates[i].position), v.dot(candidates[i].position), i});
    if (candidates[i].depth > candidates[deepest].depth) deepest = i;
  }
  std::sort(points.begin(), points.end(), [](const Projected& a, const Projected& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.index < b.index;
  });
  const auto turnsLeft = [](const Projected& o, const Projected& a, const Projected& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x) > 0.0;
  };
  for (int pass = 0; pass < 2; ++pass) {  // lower chain left to right, then upper right to left
    const std::size_t start = hull.size();
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Projected& p = points[pass == 0 ? k : points.size() - 1 - k];
      while (hull.size() >= start + 2 && !turnsLeft(hull[hull.size() - 2], hull.back(), p)) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // each chain's last point starts the other
  }
  double outlineDepth = -std::numeric_limits<double>::infinity();
  thread_local std::vector<ContactPoint> kept;
  kept.clear();
  for (const Projected& p : hull) {
    kept.push_back(candidates[p.index]);
    outlineDepth = std::max(outlineDepth, candidates[p.index].depth);
  }
  if (candidates[deepest].depth > outlineDepth + kReductionTolerance) kept.push_back(candidates[deepest]);
  candidates.swap(kept);
}

}  // namespace

ContactManifold collidePlaneConvex(const Plane& plane, const std::vector<Vec3>& vertices, double margin,
                                   double supportSlab) {
  // Scratch kept per thread (the narrow phase collides on several): a step collides every body
  // near a plane, and allocating here was most of a settled pyramid's allocations per step.
  thread_local std::vector<ContactPoint> candidates, visible;
  candidates.clear();
  visible.clear();
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : vertices) {
    const double s = plane.signedDistance(p);
    if (s > margin) continue;
    candidates.push_back({p - plane.normal * (0.5 * s), -s});
    deepest = std::max(deepest, -s);
  }
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const ContactPoint& c) { return c.depth < deepest - supportSlab; }),
                   candidates.end());
  if (candidates.size() > kPlaneHullCandidates) keepOutline(candidates, plane.normal);
  // A vertex above a deeper one, higher by more than it lies beside it, is shadowed: the deeper
  // vertex meets the plane first and holds the body there. Reduction by area sees the plane's
  // projection only, so without this it may keep the top corner of a thin plate (within the
  // margin, at the same place seen from above) and drop the bottom corner under it, which then
  // sinks unopposed.
  for (const ContactPoint& c : candidates) {
    const bool shadowed = std::any_of(candidates.begin(), candidates.end(), [&](const ContactPoint& d) {
      const Vec3 beside = d.position - c.position - plane.normal * plane.normal.dot(d.position - c.position);
      return d.depth - c.depth > beside.norm();
    });
    if (!shadowed) visible.push_back(c);
  }
  return reduceContacts(visible, plane.normal);
}

}  // namespace rbsim
