#include "geometry/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "geometry/distance.h"
#include "geometry/triangle_edges.h"

namespace rbsim {

namespace {

// Squared distance from p to the box (0 inside).
double squaredDistanceToBox(const Vec3& p, const Aabb& box) {
  return (box.min - p).cwiseMax(p - box.max).cwiseMax(0.0).squaredNorm();
}

// Slab test of the closed segment a + t (b - a), t in [0, 1], against the closed box.
bool segmentMeetsBox(const Vec3& a, const Vec3& b, const Aabb& box) {
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = b[axis] - a[axis];
    if (d == 0.0) {
      if (a[axis] < box.min[axis] || a[axis] > box.max[axis]) return false;
      continue;
    }
    double lo = (box.min[axis] - a[axis]) / d, hi = (box.max[axis] - a[axis]) / d;
    if (lo > hi) std::swap(lo, hi);
    t0 = std::max(t0, lo);
    t1 = std::min(t1, hi);
    if (t0 > t1) return false;
  }
  return true;
}

// Whether segment pq passes through the interior of triangle abc, both ends clearly on either
// side of its plane and the meeting point clearly inside (margin kSelfCrossingTolerance).
bool edgePierces(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& point) {
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0.0)) return false;
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  const double side = kSelfCrossingTolerance * std::sqrt(n2) * (q - p).norm();
  if (!((dp > side && dq < -side) || (dp < -side && dq > side))) return false;
  const Vec3 x = p + (dp / (dp - dq)) * (q - p);
  // Barycentric coordinates of x from the sub-triangles' areas, each clearly positive.
  const double u = n.dot((c - b).cross(x - b)) / n2, v = n.dot((a - c).cross(x - c)) / n2;
  const double w = 1.0 - u - v;
  if (!(u >= -kSelfCrossingTolerance && v >= -kSelfCrossingTolerance && w >= -kSelfCrossingTolerance)) return false;
  point = x;
  return true;
}

}  // namespace

bool trianglesCross(const Vec3 (&t)[3], const Vec3 (&u)[3], Vec3& point) {
  for (int e = 0; e < 3; ++e) {
    if (edgePierces(t[e], t[(e + 1) % 3], u[0], u[1], u[2], point)) return true;
    if (edgePierces(u[e], u[(e + 1) % 3], t[0], t[1], t[2], point)) return true;
  }
  return false;
}

bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                            const Vec3& c, double& t) {
  // Moller and Trumbore 1997: solve p + t (q - p) = a + u (b - a) + v (c - a) by Cramer's rule.
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 pvec = d.cross(e2);
  const double det = e1.dot(pvec);
  // Parallel to the plane (relative to |d| |e1 x e2|, so the test is scale-free).
  if (std::abs(det) <= kSegmentTriangleTolerance * d.norm() * e1.cross(e2).norm()) return false;
  const double inv = 1.0 / det;
  const Vec3 tvec = p - a;
  const double u = tvec.dot(pvec) * inv;
  if (u < -kSegmentTriangleTolerance || u > 1.0 + kSegmentTriangleTolerance) return false;
  const Vec3 qvec = tvec.cross(e1);
  const double v = d.dot(qvec) * inv;
  if (v < -kSegmentTriangleTolerance || u + v > 1.0 + kSegmentTriangleTolerance) return false;
  t = e2.dot(qvec) * inv;
  return t >= -kSegmentTriangleTolerance && t <= 1.0 + kSegmentTriangleTolerance;
}

TriangleBvh::TriangleBvh(const Mesh& mesh) : vertices_(mesh.vertices), triangles_(mesh.triangles) {
  if (triangles_.empty()) {
    throw std::invalid_argument("TriangleBvh: mesh '" + mesh.name + "' has no triangles");
  }
  std::vector<Vec3> centroids(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    for (std::uint32_t v : triangles_[t]) {
      if (v >= vertices_.size()) {
        throw std::invalid_argument("TriangleBvh: mesh '" + mesh.name + "' triangle " +
                                    std::to_string(t) + " indexes vertex " + std::to_string(v) +
                                    " of " + std::to_string(vertices_.size()));
      }
    }
    const Triangle& tri = triangles_[t];
    centroids[t] = (vertices_[tri[0]] + vertices_[tri[1]] + vertices_[tri[2]]) / 3.0;
  }
  order_.resize(triangles_.size());
  for (std::uint32_t t = 0; t < order_.size(); ++t) order_[t] = t;
  nodes_.reserve(2 * triangles_.size());
  nodes_.emplace_back();
  buildNode(0, 0, static_cast<std::uint32_t>(order_.size()), centroids);
  activeEdges_ = rbsim::activeEdges(vertices_, triangles_);
}

// Top-down: split at the median centroid along the longest axis of the centroids' box. The
// median split keeps the tree balanced (depth log2(n / leaf)), and the order is a pure function
// of the mesh, so the tree and every query are deterministic.
// Children are allocated side by side before either is built, so the right child is first + 1.
void TriangleBvh::buildNode(std::uint32_t index, std::uint32_t begin, std::uint32_t end,
                            const std::vector<Vec3>& centroids) {
  Aabb box, centroidBox;
  for (std::uint32_t i = begin; i < end; ++i) {
    for (std::uint32_t v : triangles_[order_[i]]) box.grow(vertices_[v]);
    centroidBox.grow(centroids[order_[i]]);
  }
  nodes_[index].box = box;
  if (end - begin <= kBvhLeafTriangles) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return;
  }
  Eigen::Index axis = 0;
  centroidBox.extents().maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t x, std::uint32_t y) {
                     const double cx = centroids[x][axis], cy = centroids[y][axis];
                     return cx < cy || (cx == cy && x < y);
                   });
  const std::uint32_t left = static_cast<std::uint32_t>(nodes_.size());
  nodes_[index].first = left;
  nodes_.emplace_back();
  nodes_.emplace_back();
  buildNode(left, begin, mid, centroids);
  buildNode(left + 1, mid, end, centroids);
}

void TriangleBvh::closest(const Vec3& p, double& best2, SurfacePoint& best) const {
  // Depth first, nearer child first, pruning boxes farther than the best so far.
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (squaredDistanceToBox(p, node.box) > best2) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const Triangle& tri = triangles_[order_[i]];
        const PointTriangleResult r =
            closestPointOnTriangle(p, vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
        const double d2 = r.distance * r.distance;
        if (d2 <= best2) {
          best2 = d2;
          best = {r.closest, r.distance, order_[i]};
        }
      }
      continue;
    }
    const std::uint32_t left = node.first, right = node.first + 1;
    const double dl = squaredDistanceToBox(p, nodes_[left].box);
    const double dr = squaredDistanceToBox(p, nodes_[right].box);
    // Pushed last is visited first.
    if (dl <= dr) {
      stack[top++] = right;
      stack[top++] = left;
    } else {
      stack[top++] = left;
      stack[top++] = right;
    }
  }
}

void TriangleBvh::overlapping(const Aabb& box, std::vector<std::uint32_t>& out) const {
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.overlaps(box)) continue;
    if (node.count == 0) {
      stack[top++] = node.first + 1;
      stack[top++] = node.first;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const Triangle& t = triangles_[order_[i]];
      Aabb own;
      for (std::uint32_t v : t) own.grow(vertices_[v]);
      if (own.overlaps(box)) out.push_back(order_[i]);
    }
  }
}

std::optional<SurfacePoint> TriangleBvh::closestWithin(const Vec3& p, double radius) const {
  double best2 = radius * radius;
  SurfacePoint best;
  best.distance = std::numeric_limits<double>::infinity();
  closest(p, best2, best);
  if (!(best.distance <= radius)) return std::nullopt;
  return best;
}

SurfacePoint TriangleBvh::nearest(const Vec3& p) const {
  double best2 = std::numeric_limits<double>::infinity();
  SurfacePoint best;
  closest(p, best2, best);
  return best;
}

SegmentCrossings TriangleBvh::crossings(const Vec3& a, const Vec3& b) const {
  SegmentCrossings out;
  double tFirst = std::numeric_limits<double>::infinity();
  double tLast = -std::numeric_limits<double>::infinity();
  // Boxes are grown by the tolerance's length so the tolerant triangle test is never pre-empted.
  const double margin = kSegmentTriangleTolerance * (bounds().extents().norm() + (b - a).norm());
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!segmentMeetsBox(a, b, node.box.inflated(margin))) continue;
    if (node.count == 0) {
      stack[top++] = node.first + 1;
      stack[top++] = node.first;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const std::uint32_t t = order_[i];
      const Triangle& tri = triangles_[t];
      double s = 0.0;
      if (!segmentCrossesTriangle(a, b, vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]], s)) {
        continue;
      }
      ++out.count;
      if (s < tFirst || (s == tFirst && t < out.firstTriangle)) {
        tFirst = s;
        out.firstTriangle = t;
      }
      if (s > tLast || (s == tLast && t < out.lastTriangle)) {
        tLast = s;
        out.lastTriangle = t;
      }
    }
  }
  return out;
}

void TriangleBvh::crossLeaves(const Node& a, const Node& b, bool same, double maxPairTests,
                              SelfCrossing& out) const {
  for (std::uint32_t i = a.first; i < a.first + a.count && !out.found && !out.exhausted; ++i) {
    const std::uint32_t ti = order_[i];
    const Triangle& x = triangles_[ti];
    const Vec3 tx[3] = {vertices_[x[0]], vertices_[x[1]], vertices_[x[2]]};
    for (std::uint32_t j = same ? i + 1 : b.first; j < b.first + b.count; ++j) {
      const std::uint32_t tj = order_[j];
      const Triangle& y = triangles_[tj];
      int shared = 0;
      for (std::uint32_t v : x) shared += (v == y[0]) + (v == y[1]) + (v == y[2]);
      if (shared >= 2) continue;  // neighbours across an edge
      if (++out.pairTests > maxPairTests) {
        out.exhausted = true;
        return;
      }
      const Vec3 ty[3] = {vertices_[y[0]], vertices_[y[1]], vertices_[y[2]]};
      if (trianglesCross(tx, ty, out.point)) {
        out.found = true;
        out.first = std::min(ti, tj);
        out.second = std::max(ti, tj);
        return;
      }
    }
  }
}

SelfCrossing TriangleBvh::selfCrossing(double maxPairTests) const {
  // Simultaneous descent of the tree against itself: a node with itself splits into its children
  // with themselves and with each other; two nodes whose boxes overlap split the larger one.
  SelfCrossing out;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
  while (!stack.empty() && !out.found && !out.exhausted) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const Node& a = nodes_[ia];
    const Node& b = nodes_[ib];
    if (ia == ib) {
      if (a.count > 0) {
        crossLeaves(a, a, true, maxPairTests, out);
      } else {
        stack.push_back({a.first, a.first + 1});
        stack.push_back({a.first + 1, a.first + 1});
        stack.push_back({a.first, a.first});
      }
      continue;
    }
    if (!a.box.overlaps(b.box)) continue;
    if (a.count > 0 && b.count > 0) {
      crossLeaves(a, b, false, maxPairTests, out);
    } else if (b.count > 0 || (a.count == 0 && a.box.extents().squaredNorm() >= b.box.extents().squaredNorm())) {
      stack.push_back({a.first + 1, ib});
      stack.push_back({a.first, ib});
    } else {
      stack.push_back({ia, b.first + 1});
      stack.push_back({ia, b.first});
    }
  }
  return out;
}

void TriangleBvh::overlappingPairs(const TriangleBvh& other, const Mat3& rotation, const Vec3& translation,
                                   const std::function<void(std::uint32_t, std::uint32_t)>& pair) const {
  const Mat3 spread = rotation.cwiseAbs();
  const auto placed = [&](const Aabb& box) {  // the box of `box` rotated and moved into this frame
    const Vec3 centre = rotation * (0.5 * (box.min + box.max)) + translation;
    const Vec3 half = spread * (0.5 * (box.max - box.min));
    return Aabb{centre - half, centre + half};
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const Node& a = nodes_[ia];
    const Node& b = other.nodes_[ib];
    const Aabb bBox = placed(b.box);
    if (!a.box.overlaps(bBox)) continue;
    if (a.count > 0 && b.count > 0) {
      for (std::uint32_t i = a.first; i < a.first + a.count; ++i) {
        for (std::uint32_t j = b.first; j < b.first + b.count; ++j) pair(order_[i], other.order_[j]);
      }
    } else if (b.count > 0 || (a.count == 0 && a.box.extents().squaredNorm() >= bBox.extents().squaredNorm())) {
      stack.push_back({a.first + 1, ib});
      stack.push_back({a.first, ib});
    } else {
      stack.push_back({ia, b.first + 1});
      stack.push_back({ia, b.first});
    }
  }
}

}  // namespace rbsim
