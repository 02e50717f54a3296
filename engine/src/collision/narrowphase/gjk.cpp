#include "collision/narrowphase/gjk.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/distance.h"

namespace rbsim {

namespace {

// A tetrahedron whose |6 volume| is below this fraction of its longest edge cubed [1] is flat:
// the origin is then tested against its four faces only, never declared inside it.
constexpr double kFlatTetrahedronRatio = 1e-12;

// Two support points closer than this [m] are the same vertex: adding it again cannot progress.
constexpr double kDuplicateSupportDistance = 1e-14;

// Keeps the simplex vertices with the given indices and weights, in order.
void keep(GjkSimplex& s, std::array<double, 4>& lambda, const int* idx, const double* w, int n) {
  GjkSimplex out;
  std::array<double, 4> l{};
  for (int k = 0; k < n; ++k) {
    out.points[k] = s.points[idx[k]];
    l[k] = w[k];
  }
  out.size = n;
  s = out;
  lambda = l;
}

// Reduces a triangle (i, j, k) of the simplex to the feature holding its closest point to O.
void keepTriangleFeature(GjkSimplex& s, std::array<double, 4>& lambda, int i, int j, int k,
                         const PointTriangleResult& r) {
  const int ids[3] = {i, j, k};
  int idx[3];
  double w[3];
  int n = 0;
  for (int m = 0; m < 3; ++m) {
    if (r.barycentric[m] > 0.0) {
      idx[n] = ids[m];
      w[n++] = r.barycentric[m];
    }
  }
  keep(s, lambda, idx, w, n);
}

}  // namespace

Vec3 closestToOrigin(GjkSimplex& s, std::array<double, 4>& lambda) {
  const Vec3 o = Vec3::Zero();
  switch (s.size) {
    case 1:
      lambda = {1.0, 0.0, 0.0, 0.0};
      break;
    case 2: {
      const PointSegmentResult r = closestPointOnSegment(o, s.points[0].w, s.points[1].w);
      if (r.feature == SegmentFeature::Interior) {
        const int idx[2] = {0, 1};
        const double w[2] = {1.0 - r.t, r.t};
        keep(s, lambda, idx, w, 2);
      } else {
        const int idx[1] = {r.feature == SegmentFeature::Start ? 0 : 1};
        const double w[1] = {1.0};
        keep(s, lambda, idx, w, 1);
      }
      break;
    }
    case 3:
      keepTriangleFeature(s, lambda, 0, 1, 2,
                          closestPointOnTriangle(o, s.points[0].w, s.points[1].w, s.points[2].w));
      break;
    default: {
      // Ericson §5.1.6 ClosestPtPointTetrahedron: the nearest of the faces whose plane separates
      // the origin from the opposite vertex; inside when there is none.
      const Vec3& p0 = s.points[0].w;
      const Vec3& p1 = s.points[1].w;
      const Vec3& p2 = s.points[2].w;
      const Vec3& p3 = s.points[3].w;
      double longest = 0.0;
      for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (s.points[i].w - s.points[j].w).norm());
      }
      const double volume6 = (p1 - p0).dot((p2 - p0).cross(p3 - p0));
      const bool flat = std::abs(volume6) <= kFlatTetrahedronRatio * longest * longest * longest;
      static constexpr int kFaces[4][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}};
      double best = std::numeric_limits<double>::infinity();
      int bestFace = -1;
      PointTriangleResult bestResult;
      for (int f = 0; f < 4; ++f) {
        const Vec3& a = s.points[kFaces[f][0]].w;
        const Vec3& b = s.points[kFaces[f][1]].w;
        const Vec3& c = s.points[kFaces[f][2]].w;
        const Vec3& d = s.points[kFaces[f][3]].w;
        const Vec3 n = (b - a).cross(c - a);
        const bool outside = flat || (n.dot(o - a) * n.dot(d - a) < 0.0);
        if (!outside) continue;
        const PointTriangleResult r = closestPointOnTriangle(o, a, b, c);
        if (r.distance < best) {
          best = r.distance;
          bestFace = f;
          bestResult = r;
        }
      }
      if (bestFace < 0) {
        // Inside: the weights are the sub-volumes opposite each vertex over the whole volume.
        const double inv = 1.0 / volume6;
        lambda = {p1.cross(p2).dot(p3) * inv, -p0.cross(p2).dot(p3) * inv, p0.cross(p1).dot(p3) * inv,
                  -p0.cross(p1).dot(p2) * inv};
        return Vec3::Zero();
      }
      keepTriangleFeature(s, lambda, kFaces[bestFace][0], kFaces[bestFace][1], kFaces[bestFace][2],
                          bestResult);
      break;
    }
  }
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < s.size; ++k) v += lambda[k] * s.points[k].w;
  return v;
}

std::size_t supportIndex(const std::vector<Vec3>& points, const Vec3& direction) {
  std::size_t best = 0;
  double bestDot = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = direction.dot(points[i]);
    if (d > bestDot) {
      bestDot = d;
      best = i;
    }
  }
  return best;
}

SupportPoint minkowskiSupport(const SupportMap& a, const SupportMap& b, const Vec3& direction) {
  SupportPoint s;
  s.a = a.support(direction);
  s.b = b.support(-direction);
  s.w = s.a - s.b;
  return s;
}

SupportPoint minkowskiSupport(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& direction) {
  return minkowskiSupport(PointSetSupport(a), PointSetSupport(b), direction);
}

GjkResult gjk(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.empty() || b.empty()) {
    GjkResult r;
    r.distance = std::numeric_limits<double>::infinity();
    return r;
  }
  return gjk(PointSetSupport(a), PointSetSupport(b));
}

GjkResult gjk(const SupportMap& a, const SupportMap& b) {
  GjkResult r;
  GjkSimplex& s = r.simplex;
  const Vec3 a0 = a.anyPoint(), b0 = b.anyPoint();
  s.points[0] = {a0 - b0, a0, b0};
  s.size = 1;
  std::array<double, 4> lambda = {1.0, 0.0, 0.0, 0.0};
  Vec3 v = s.points[0].w;
  r.overlap = v.norm() <= kGjkOverlapTolerance;
  while (!r.overlap && r.iterations < kGjkMaxIterations) {
    ++r.iterations;
    const SupportPoint w = minkowskiSupport(a, b, -v);
    const double vv = v.squaredNorm();
    // van den Bergen's termination: |v| - v.w / |v| bounds the distance error from above.
    if (vv - v.dot(w.w) <= kGjkDistanceTolerance * std::sqrt(vv)) break;
    bool duplicate = false;
    for (int k = 0; k < s.size; ++k) duplicate |= (s.points[k].w - w.w).norm() <= kDuplicateSupportDistance;
    if (duplicate) break;
    const GjkSimplex before = s;
    const std::array<double, 4> lambdaBefore = lambda;
    s.points[s.size++] = w;
    const Vec3 next = closestToOrigin(s, lambda);
    if (next.norm() <= kGjkOverlapTolerance) {
      v = next;
      r.overlap = true;
    } else if (next.squaredNorm() >= vv) {
      // No progress: rounding has reached the answer; keep the previous, no worse, simplex.
      s = before;
      lambda = lambdaBefore;
      break;
    } else {
      v = next;
    }
  }
  r.pointA = Vec3::Zero();
  r.pointB = Vec3::Zero();
  for (int k = 0; k < s.size; ++k) {
    r.pointA += lambda[k] * s.points[k].a;
    r.pointB += lambda[k] * s.points[k].b;
  }
  r.distance = r.overlap ? 0.0 : v.norm();
  return r;
}

}  // namespace rbsim
