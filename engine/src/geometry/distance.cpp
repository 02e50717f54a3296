#include "geometry/distance.h"

#include <algorithm>

namespace rbsim {

namespace {

// Below this sin^2 of the angle between two segments [1] they are treated as parallel: the
// closest-point formula's denominator a e - b^2 = a e sin^2 would be rounding noise.
constexpr double kParallelSegmentsSinSquared = 1e-16;

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

// The closest point of edge k (0 = ab, 1 = bc, 2 = ca) as a triangle result.
PointTriangleResult fromEdge(const PointSegmentResult& r, int edge) {
  static constexpr TriangleFeature kStart[3] = {TriangleFeature::VertexA, TriangleFeature::VertexB,
                                                TriangleFeature::VertexC};
  static constexpr TriangleFeature kEdge[3] = {TriangleFeature::EdgeAB, TriangleFeature::EdgeBC,
                                               TriangleFeature::EdgeCA};
  PointTriangleResult out;
  out.closest = r.closest;
  out.distance = r.distance;
  const int i = edge, j = (edge + 1) % 3;
  out.barycentric = {0.0, 0.0, 0.0};
  out.barycentric[i] = 1.0 - r.t;
  out.barycentric[j] = r.t;
  switch (r.feature) {
    case SegmentFeature::Start: out.feature = kStart[i]; break;
    case SegmentFeature::End: out.feature = kStart[j]; break;
    case SegmentFeature::Interior: out.feature = kEdge[i]; break;
  }
  return out;
}

PointTriangleResult make(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double u,
                         double v, double w, TriangleFeature feature) {
  PointTriangleResult out;
  out.closest = u * a + v * b + w * c;
  out.barycentric = {u, v, w};
  out.distance = (p - out.closest).norm();
  out.feature = feature;
  return out;
}

}  // namespace

double pointPointDistance(const Vec3& p0, const Vec3& p1) { return (p0 - p1).norm(); }

PointSegmentResult closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  PointSegmentResult r;
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 > kDegenerateSegmentLength * kDegenerateSegmentLength) {
    r.t = clamp01((p - a).dot(ab) / len2);
  }
  r.feature = r.t <= 0.0 ? SegmentFeature::Start
              : r.t >= 1.0 ? SegmentFeature::End
                           : SegmentFeature::Interior;
  r.closest = r.feature == SegmentFeature::End ? b : a + r.t * ab;
  r.distance = (p - r.closest).norm();
  return r;
}

PointTriangleResult closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, bc = c - b;
  const double longest2 = std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()});
  if (ab.cross(ac).norm() <= kDegenerateTriangleRatio * longest2) {
    PointTriangleResult best = fromEdge(closestPointOnSegment(p, a, b), 0);
    for (int e = 1; e < 3; ++e) {
      const Vec3& s = e == 1 ? b : c;
      const Vec3& t = e == 1 ? c : a;
      const PointTriangleResult r = fromEdge(closestPointOnSegment(p, s, t), e);
      if (r.distance < best.distance) best = r;
    }
    return best;
  }
  // Ericson §5.1.5 ClosestPtPointTriangle: test the vertex regions, then the edge regions, by the
  // signs of dot products; what is left is the face region. The triangle is not degenerate, so
  // every denominator below is a positive squared length or squared area.
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return make(p, a, b, c, 1, 0, 0, TriangleFeature::VertexA);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return make(p, a, b, c, 0, 1, 0, TriangleFeature::VertexB);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return make(p, a, b, c, 1 - v, v, 0, TriangleFeature::EdgeAB);
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return make(p, a, b, c, 0, 0, 1, TriangleFeature::VertexC);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return make(p, a, b, c, 1 - w, 0, w, TriangleFeature::EdgeCA);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return make(p, a, b, c, 0, 1 - w, w, TriangleFeature::EdgeBC);
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return make(p, a, b, c, 1 - v - w, v, w, TriangleFeature::Face);
}

SegmentSegmentResult closestPointsSegmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2,
                                                 const Vec3& q2) {
  // Ericson §5.1.9 ClosestPtSegmentSegment: minimise |p1 + s d1 - p2 - t d2|^2 over the unit
  // square; the unconstrained s is clamped, t follows from s, and s is recomputed if t clamps.
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  const double tiny = kDegenerateSegmentLength * kDegenerateSegmentLength;
  double s = 0.0, t = 0.0;
  if (a <= tiny && e <= tiny) {
    // Both are points.
  } else if (a <= tiny) {
    t = clamp01(f / e);
  } else {
    const double c = d1.dot(r);
    if (e <= tiny) {
      s = clamp01(-c / a);
    } else {
      const double b = d1.dot(d2);
      const double denom = a * e - b * b;
      s = denom > kParallelSegmentsSinSquared * a * e ? clamp01((b * f - c * e) / denom) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = clamp01(-c / a);
      } else if (t > 1.0) {
        t = 1.0;
        s = clamp01((b - c) / a);
      }
    }
  }
  SegmentSegmentResult out;
  out.s = s;
  out.t = t;
  out.closest1 = p1 + s * d1;
  out.closest2 = p2 + t * d2;
  out.distance = (out.closest1 - out.closest2).norm();
  return out;
}

}  // namespace rbsim
