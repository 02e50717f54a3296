#include "collision/narrowphase/box_box.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/distance.h"
#include "collision/narrowphase/manifold_reduction.h"
#include "collision/narrowphase/polygon_clip.h"

namespace rbsim {

namespace {

// A quad clipped by the four side planes of a face: each plane adds at most one vertex.
constexpr std::size_t kMaxClippedQuad = 8;

// A mesh vertex within this fraction of the box's largest extent [1] of a bound is on it.
constexpr double kBoxCornerRelTolerance = 1e-9;

// Separation of the boxes' projections on unit axis L: |L.d| - r_A - r_B (OBBTree §4).
double axisSeparation(const OrientedBox& a, const OrientedBox& b, const Vec3& d, const Vec3& L) {
  double ra = 0.0, rb = 0.0;
  for (int k = 0; k < 3; ++k) {
    ra += a.halfExtents[k] * std::abs(L.dot(a.rotation.col(k)));
    rb += b.halfExtents[k] * std::abs(L.dot(b.rotation.col(k)));
  }
  return std::abs(L.dot(d)) - ra - rb;
}

// Face contact: the incident box's face most opposed to the reference face, clipped to the
// reference face's four side planes; points within the margin of the reference face are kept.
ContactManifold faceContact(const OrientedBox& ref, int axis, const OrientedBox& inc, bool refIsA,
                            double margin) {
  const Vec3 toInc = inc.centre - ref.centre;
  const Vec3 nRef = ref.rotation.col(axis) * (ref.rotation.col(axis).dot(toInc) >= 0.0 ? 1.0 : -1.0);
  const Vec3 refCentre = ref.centre + nRef * ref.halfExtents[axis];

  int m = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(nRef.dot(inc.rotation.col(k))) > std::abs(nRef.dot(inc.rotation.col(m)))) m = k;
  }
  const Vec3 incNormal = inc.rotation.col(m) * (nRef.dot(inc.rotation.col(m)) > 0.0 ? -1.0 : 1.0);
  const Vec3 incCentre = inc.centre + incNormal * inc.halfExtents[m];
  const Vec3 u = inc.rotation.col((m + 1) % 3) * inc.halfExtents[(m + 1) % 3];
  const Vec3 v = inc.rotation.col((m + 2) % 3) * inc.halfExtents[(m + 2) % 3];
  // Clipped in two buffers on the stack: a step collides thousands of pairs, and allocating here
  // was most of a step's 9500 allocations on a 210-box pyramid.
  std::array<Vec3, kMaxClippedQuad> polygon{incCentre + u + v, incCentre - u + v, incCentre - u - v, incCentre + u - v};
  std::array<Vec3, kMaxClippedQuad> clipped;
  std::size_t count = 4;
  for (int k = 0; k < 3 && count > 0; ++k) {
    if (k == axis) continue;
    const Vec3 side = ref.rotation.col(k);
    const double c = side.dot(ref.centre);
    count = clipByHalfSpace(polygon.data(), count, side, c + ref.halfExtents[k], clipped.data());
    count = clipByHalfSpace(clipped.data(), count, -side, -c + ref.halfExtents[k], polygon.data());
  }
  std::array<ContactPoint, kMaxClippedQuad> candidates;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const double s = nRef.dot(polygon[i] - refCentre);
    if (s <= margin) candidates[kept++] = {polygon[i] - nRef * (0.5 * s), -s};
  }
  return reduceContacts(candidates.data(), kept, refIsA ? nRef : Vec3(-nRef));
}

// Edge contact: the closest points of A's edge along axis i furthest along n and B's edge along
// axis j furthest along -n.
ContactManifold edgeContact(const OrientedBox& a, int i, const OrientedBox& b, int j, const Vec3& n) {
  Vec3 pa = a.centre, pb = b.centre;
  for (int k = 0; k < 3; ++k) {
    if (k != i) pa += a.rotation.col(k) * (a.halfExtents[k] * (n.dot(a.rotation.col(k)) >= 0.0 ? 1.0 : -1.0));
    if (k != j) pb -= b.rotation.col(k) * (b.halfExtents[k] * (n.dot(b.rotation.col(k)) >= 0.0 ? 1.0 : -1.0));
  }
  const Vec3 ea = a.rotation.col(i) * a.halfExtents[i], eb = b.rotation.col(j) * b.halfExtents[j];
  const SegmentSegmentResult c = closestPointsSegmentSegment(pa - ea, pa + ea, pb - eb, pb + eb);
  ContactManifold m;
  m.normal = n;
  m.add(0.5 * (c.closest1 + c.closest2), n.dot(c.closest1 - c.closest2));
  return m;
}

}  // namespace

BoxBoxResult collideBoxes(const OrientedBox& a, const OrientedBox& b, double margin) {
  BoxBoxResult r;
  const Vec3 d = b.centre - a.centre;
  double sFaceA = -std::numeric_limits<double>::infinity(), sFaceB = sFaceA, sEdge = sFaceA;
  int iFaceA = 0, iFaceB = 0, iEdge = 0, jEdge = 0;
  Vec3 edgeAxis = Vec3::UnitX();
  const auto separated = [&](double s) {
    if (s <= margin) return false;
    r.separation = s;
    r.manifold.count = 0;
    return true;
  };
  for (int k = 0; k < 3; ++k) {
    const double sa = axisSeparation(a, b, d, a.rotation.col(k));
    if (separated(sa)) return r;
    if (sa > sFaceA) {
      sFaceA = sa;
      iFaceA = k;
    }
    const double sb = axisSeparation(a, b, d, b.rotation.col(k));
    if (separated(sb)) return r;
    if (sb > sFaceB) {
      sFaceB = sb;
      iFaceB = k;
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Vec3 L = a.rotation.col(i).cross(b.rotation.col(j));
      const double len = L.norm();
      if (len < kSatParallelEdgeSine) continue;
      L /= len;
      const double s = axisSeparation(a, b, d, L);
      if (separated(s)) return r;
      if (s > sEdge) {
        sEdge = s;
        iEdge = i;
        jEdge = j;
        edgeAxis = L;
      }
    }
  }

  double sFace = sFaceA;
  r.axis = SatAxisKind::FaceA;
  r.indexA = iFaceA;
  if (sFaceB > sFaceA + kSatFaceRelTolerance * std::abs(sFaceA) + kSatFaceAbsTolerance) {
    sFace = sFaceB;
    r.axis = SatAxisKind::FaceB;
    r.indexB = iFaceB;
  }
  if (sEdge > sFace + kSatEdgeRelTolerance * std::abs(sFace) + kSatEdgeAbsTolerance) {
    r.axis = SatAxisKind::EdgeEdge;
    r.indexA = iEdge;
    r.indexB = jEdge;
    r.separation = sEdge;
    r.manifold = edgeContact(a, iEdge, b, jEdge, edgeAxis.dot(d) >= 0.0 ? edgeAxis : Vec3(-edgeAxis));
    return r;
  }
  r.separation = sFace;
  r.manifold = r.axis == SatAxisKind::FaceA ? faceContact(a, iFaceA, b, true, margin)
                                            : faceContact(b, iFaceB, a, false, margin);
  return r;
}

std::optional<OrientedBox> orientedBoxOf(const Mesh& mesh, const Vec3& position, const Mat3& rotation) {
  if (mesh.vertices.size() != 8) return std::nullopt;
  const Vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax();
  const double tol = kBoxCornerRelTolerance * (hi - lo).maxCoeff();
  if (!((hi - lo).minCoeff() > tol)) return std::nullopt;
  int corners = 0;  // bit k set: the corner with x, y, z at (k & 1, k & 2, k & 4) ? hi : lo
  for (const Vec3& p : mesh.vertices) {
    int k = 0;
    for (int c = 0; c < 3; ++c) {
      if (std::abs(p[c] - hi[c]) <= tol) k |= 1 << c;
      else if (std::abs(p[c] - lo[c]) > tol) return std::nullopt;
    }
    corners |= 1 << k;
  }
  if (corners != 0xff) return std::nullopt;
  OrientedBox box;
  box.centre = rotation * (0.5 * (lo + hi)) + position;
  box.rotation = rotation;
  box.halfExtents = 0.5 * (hi - lo);
  return box;
}

}  // namespace rbsim
