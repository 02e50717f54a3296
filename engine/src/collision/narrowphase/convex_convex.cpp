#include "collision/narrowphase/convex_convex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/distance.h"
#include "collision/narrowphase/epa.h"
#include "collision/narrowphase/gjk.h"
#include "collision/narrowphase/manifold_reduction.h"
#include "collision/narrowphase/polygon_clip.h"

namespace rbsim {

namespace {

// Feature hull vertices within this [m] of the line through their neighbours are dropped.
constexpr double kFeatureHullTolerance = 1e-9;
// Two edge features whose directions in the contact plane have a sine below this [1] are
// parallel: they overlap along a stretch (two points) instead of crossing at one.
constexpr double kParallelFeatureSine = 1e-6;

// A support feature: its hull seen along n (1 point, 2 for an edge, >= 3 for a face).
struct Feature {
  std::vector<Vec3> hull;
};

// The buffers below are kept per thread (the narrow phase collides on several threads), so that a
// steady step of a pile of hulls allocates nothing; none of these functions calls itself.
void supportFeature(const std::vector<Vec3>& points, const Vec3& dir, const Vec3& n, double tolerance, Feature& out) {
  double extreme = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : points) extreme = std::max(extreme, dir.dot(p));
  thread_local std::vector<Vec3> near;
  near.clear();
  for (const Vec3& p : points) {
    if (dir.dot(p) >= extreme - tolerance) near.push_back(p);
  }
  planarConvexHull(near, n, kFeatureHullTolerance, out.hull);
}

// Height along n of the feature's surface above the point p (p moved along n onto the feature).
double heightAt(const Feature& f, const Vec3& p, const Vec3& n) {
  const std::vector<Vec3>& h = f.hull;
  if (h.size() == 1) return n.dot(h[0]);
  if (h.size() == 2) {
    const Vec3 e = h[1] - h[0] - n * n.dot(h[1] - h[0]);
    const double t = std::clamp((p - h[0]).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (1.0 - t) * n.dot(h[0]) + t * n.dot(h[1]);
  }
  // The plane through the hull's widest triangle (as seen along n, so m . n > 0).
  std::size_t bi = 1, bj = 2;
  double best = -1.0;
  for (std::size_t i = 1; i < h.size(); ++i) {
    for (std::size_t j = i + 1; j < h.size(); ++j) {
      const double area = (h[i] - h[0]).cross(h[j] - h[0]).dot(n);
      if (area > best) {
        best = area;
        bi = i;
        bj = j;
      }
    }
  }
  const Vec3 m = (h[bi] - h[0]).cross(h[bj] - h[0]);
  return n.dot(p) + m.dot(h[0] - p) / m.dot(n);
}

// The part of `subject` inside the prism of the convex polygon `ref` (>= 3 vertices,
// counter-clockwise about n) along n, into `out`.
void clipToPrism(const std::vector<Vec3>& subject, const std::vector<Vec3>& ref, const Vec3& n, std::vector<Vec3>& out) {
  thread_local std::vector<Vec3> other;
  out.assign(subject.begin(), subject.end());
  for (std::size_t i = 0; i < ref.size() && !out.empty(); ++i) {
    const Vec3 outward = (ref[(i + 1) % ref.size()] - ref[i]).cross(n).normalized();
    other.resize(out.size() + 1);
    other.resize(clipByHalfSpace(out.data(), out.size(), outward, outward.dot(ref[i]), other.data()));
    out.swap(other);
  }
}

// Contact candidates from the two features: points of one feature's surface over the other's,
// each placed midway between the surfaces with depth = height of A - height of B.
void featureContacts(const Feature& fa, const Feature& fb, const Vec3& n, std::vector<ContactPoint>& out) {
  out.clear();
  const auto emit = [&](const Vec3& p, double ha, double hb) {
    out.push_back({p + n * (0.5 * (ha + hb) - n.dot(p)), ha - hb});
  };
  const std::size_t na = fa.hull.size(), nb = fb.hull.size();
  if (na >= 3 || nb >= 3) {
    const bool refIsA = na >= 3;
    const Feature& ref = refIsA ? fa : fb;
    thread_local std::vector<Vec3> clipped;
    clipToPrism(refIsA ? fb.hull : fa.hull, ref.hull, n, clipped);
    for (const Vec3& p : clipped) {
      const double own = n.dot(p), other = heightAt(ref, p, n);
      if (refIsA) emit(p, other, own);
      else emit(p, own, other);
    }
  } else if (na == 1) {
    emit(fa.hull[0], n.dot(fa.hull[0]), heightAt(fb, fa.hull[0], n));
  } else if (nb == 1) {
    emit(fb.hull[0], heightAt(fa, fb.hull[0], n), n.dot(fb.hull[0]));
  } else {
    const Vec3 da = fa.hull[1] - fa.hull[0], db = fb.hull[1] - fb.hull[0];
    const double sine = da.cross(db).dot(n) / (da.norm() * db.norm());
    if (std::abs(sine) > kParallelFeatureSine) {
      const SegmentSegmentResult c = closestPointsSegmentSegment(fa.hull[0], fa.hull[1], fb.hull[0], fb.hull[1]);
      emit(0.5 * (c.closest1 + c.closest2), n.dot(c.closest1), n.dot(c.closest2));
    } else {
      // Parallel edges: the stretch of B's edge within the slab of A's edge.
      const Vec3 e = (da - n * n.dot(da)).normalized();
      std::array<Vec3, 4> half, part;  // a segment clipped twice: at most two points each time
      const std::size_t kept = clipByHalfSpace(fb.hull.data(), fb.hull.size(), e, e.dot(fa.hull[1]), half.data());
      const std::size_t count = clipByHalfSpace(half.data(), kept, -e, -e.dot(fa.hull[0]), part.data());
      for (std::size_t i = 0; i < count; ++i) emit(part[i], heightAt(fa, part[i], n), n.dot(part[i]));
    }
  }
}

ContactManifold featureManifold(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& n,
                                double margin, double tolerance) {
  thread_local Feature fa, fb;
  thread_local std::vector<ContactPoint> candidates;
  supportFeature(a, n, n, tolerance, fa);
  supportFeature(b, -n, n, tolerance, fb);
  featureContacts(fa, fb, n, candidates);
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const ContactPoint& c) { return c.depth < -margin; }),
                   candidates.end());
  return reduceContacts(candidates, n);
}

}  // namespace

ConvexDistance convexDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const GjkResult g = gjk(a, b);
  return {g.overlap, g.distance, g.pointA, g.pointB};
}

ConvexContact collideConvex(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double margin,
                            const OrientedBox* boxA, const OrientedBox* boxB, double featureTolerance) {
  ConvexContact out;
  if (a.empty() || b.empty()) return out;
  if (boxA != nullptr && boxB != nullptr) {
    out.usedBoxSat = true;
    const BoxBoxResult sat = collideBoxes(*boxA, *boxB, margin);
    out.overlap = sat.separation <= 0.0;
    // Apart, the SAT's separation stands for the distance: a GJK run per separated pair would
    // cost a pile a tenth of its step for a figure only the query log reads.
    if (!out.overlap) {
      out.distance = sat.separation;
    } else {
      out.depth = -sat.separation;
    }
    out.manifold = sat.manifold;
    if (out.overlap && out.manifold.count > 0) {
      const ContactPoint& p = out.manifold.points[0];
      out.pointA = p.position + out.manifold.normal * (0.5 * p.depth);
      out.pointB = p.position - out.manifold.normal * (0.5 * p.depth);
    }
    return out;
  }
  return collideConvex(PointSetSupport(a), a, PointSetSupport(b), b, margin, featureTolerance);
}

ConvexContact collideConvex(const SupportMap& supportA, const std::vector<Vec3>& a, const SupportMap& supportB,
                            const std::vector<Vec3>& b, double margin, double featureTolerance) {
  ConvexContact out;
  if (a.empty() || b.empty()) return out;
  const GjkResult g = gjk(supportA, supportB);
  out.overlap = g.overlap;
  Vec3 n;
  if (!g.overlap) {
    out.distance = g.distance;
    out.pointA = g.pointA;
    out.pointB = g.pointB;
    if (g.distance > margin) return out;
    n = (g.pointB - g.pointA) / g.distance;
  } else {
    const EpaResult e = epa(supportA, supportB, g.simplex);
    if (e.valid) {
      n = e.normal;
      out.depth = e.depth;
      out.pointA = e.pointA;
      out.pointB = e.pointB;
    } else {
      // A - B is flat (both sets flat in one plane): separate along the line of the centroids.
      Vec3 ca = Vec3::Zero(), cb = Vec3::Zero();
      for (const Vec3& p : a) ca += p / static_cast<double>(a.size());
      for (const Vec3& p : b) cb += p / static_cast<double>(b.size());
      n = (cb - ca).norm() > 0.0 ? Vec3((cb - ca).normalized()) : Vec3::UnitY();
      out.pointA = a[supportIndex(a, n)];
      out.pointB = b[supportIndex(b, -n)];
      out.depth = n.dot(out.pointA - out.pointB);
    }
  }
  out.manifold = featureManifold(a, b, n, margin, featureTolerance);
  if (out.manifold.count == 0) {
    out.manifold.add(0.5 * (out.pointA + out.pointB), out.overlap ? out.depth : -out.distance);
  }
  return out;
}

}  // namespace rbsim
