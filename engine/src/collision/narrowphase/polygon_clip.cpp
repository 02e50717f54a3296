#include "collision/narrowphase/polygon_clip.h"

#include <algorithm>
#include <numeric>

namespace rbsim {

void planeBasis(const Vec3& n, Vec3& u, Vec3& v) {
  int minAxis;
  n.cwiseAbs().minCoeff(&minAxis);
  u = n.cross(Vec3::Unit(minAxis)).normalized();
  v = n.cross(u);
}

std::size_t clipByHalfSpace(const Vec3* polygon, std::size_t n, const Vec3& normal, double offset, Vec3* out) {
  std::size_t written = 0;
  if (n == 0) return 0;
  if (n == 1) {
    if (normal.dot(polygon[0]) <= offset) out[written++] = polygon[0];
    return written;
  }
  // A segment is its own closed loop of two edges; clip it directly so no vertex is doubled.
  if (n == 2) {
    const double d0 = normal.dot(polygon[0]) - offset, d1 = normal.dot(polygon[1]) - offset;
    if (d0 > 0.0 && d1 > 0.0) return 0;
    const Vec3 cut = (d0 > 0.0) != (d1 > 0.0) ? polygon[0] + (polygon[1] - polygon[0]) * (d0 / (d0 - d1)) : Vec3();
    out[written++] = d0 > 0.0 ? cut : polygon[0];
    out[written++] = d1 > 0.0 ? cut : polygon[1];
    return written;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& prev = polygon[(i + n - 1) % n];
    const Vec3& cur = polygon[i];
    const double dp = normal.dot(prev) - offset, dc = normal.dot(cur) - offset;
    // The edge prev -> cur: emit the crossing where it changes side, and cur when it is inside.
    if ((dc <= 0.0) != (dp <= 0.0)) out[written++] = prev + (cur - prev) * (dp / (dp - dc));
    if (dc <= 0.0) out[written++] = cur;
  }
  return written;
}

std::vector<Vec3> clipByHalfSpace(const std::vector<Vec3>& polygon, const Vec3& normal, double offset) {
  std::vector<Vec3> out(polygon.size() + 1);
  out.resize(clipByHalfSpace(polygon.data(), polygon.size(), normal, offset, out.data()));
  return out;
}

void planarConvexHull(const std::vector<Vec3>& points, const Vec3& axis, double tolerance, std::vector<Vec3>& out) {
  out.clear();
  if (points.size() <= 1) {
    out.assign(points.begin(), points.end());
    return;
  }
  Vec3 u, v;
  planeBasis(axis, u, v);
  thread_local std::vector<Eigen::Vector2d> q;
  thread_local std::vector<std::size_t> order, hull, kept;
  q.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) q[i] = {u.dot(points[i]), v.dot(points[i])};
  order.resize(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return q[i].x() < q[j].x() || (q[i].x() == q[j].x() && q[i].y() < q[j].y());
  });
  // o -> a -> b turns left by more than the tolerance (b's height over line o-a, scaled by |o-a|).
  const auto leftTurn = [&](std::size_t o, std::size_t a, std::size_t b) {
    const Eigen::Vector2d e = q[a] - q[o], f = q[b] - q[o];
    const double cross = e.x() * f.y() - e.y() * f.x();
    return cross > tolerance * std::max(e.norm(), f.norm());
  };
  hull.resize(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i : order) {  // lower chain
    while (k >= 2 && !leftTurn(hull[k - 2], hull[k - 1], i)) --k;
    hull[k++] = i;
  }
  for (std::size_t t = order.size() - 1, lower = k + 1; t-- > 0;) {  // upper chain
    const std::size_t i = order[t];
    while (k >= lower && !leftTurn(hull[k - 2], hull[k - 1], i)) --k;
    hull[k++] = i;
  }
  hull.resize(k - 1);  // the last point repeats the first
  // Drop vertices within tolerance of the previous one (the chains only remove turns).
  kept.clear();
  for (std::size_t i : hull) {
    if (kept.empty() || (q[i] - q[kept.back()]).norm() > tolerance) kept.push_back(i);
  }
  while (kept.size() > 1 && (q[kept.back()] - q[kept.front()]).norm() <= tolerance) kept.pop_back();
  if (kept.empty()) kept.push_back(order.front());
  if (kept.size() == 2) {
    // Flat within tolerance: the two ends of the longest extent.
    out.push_back(points[order.front()]);
    if ((q[order.back()] - q[order.front()]).norm() > tolerance) out.push_back(points[order.back()]);
    return;
  }
  for (std::size_t i : kept) out.push_back(points[i]);
}

std::vector<Vec3> planarConvexHull(const std::vector<Vec3>& points, const Vec3& axis, double tolerance) {
  std::vector<Vec3> out;
  planarConvexHull(points, axis, tolerance, out);
  return out;
}

}  // namespace rbsim
