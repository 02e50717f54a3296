#include "collision/narrowphase/convex_convex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

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
// A hull's vertex within this [m] of one of its face planes lies on that face (the planes are
// exact to shapes/face_planes.cpp's 1e-9; posing a vertex rounds by ~1e-16 of its distance from
// the origin, 1e-10 m at the 1e6 m the scene format allows).
constexpr double kOnFaceTolerance = 1e-7;

// A support feature: its hull seen along n (1 point, 2 for an edge, >= 3 for a face).
struct Feature {
  std::vector<Vec3> hull;
};

// The vertices of `points` within `tolerance` of their extreme along dir, into `out`.
void nearExtreme(const std::vector<Vec3>& points, const Vec3& dir, double tolerance, std::vector<Vec3>& out) {
  double extreme = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : points) extreme = std::max(extreme, dir.dot(p));
  out.clear();
  for (const Vec3& p : points) {
    if (dir.dot(p) >= extreme - tolerance) out.push_back(p);
  }
}

// The buffers below are kept per thread (the narrow phase collides on several threads), so that a
// steady step of a pile of hulls allocates nothing; none of these functions calls itself.
void supportFeature(const std::vector<Vec3>& points, const Vec3& dir, const Vec3& n, double tolerance, Feature& out) {
  thread_local std::vector<Vec3> near;
  nearExtreme(points, dir, tolerance, near);
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

// Whether p lies in the prism of the convex polygon `ref` (counter-clockwise about n) along n.
bool insidePrism(const Vec3& p, const std::vector<Vec3>& ref, const Vec3& n) {
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if ((ref[(i + 1) % ref.size()] - ref[i]).cross(n).dot(p - ref[i]) > 0.0) return false;
  }
  return true;
}

// Which feature is the reference face, the one the other is clipped against.
enum class Reference { A, B, None };

// Contact candidates from the two features: points of one feature's surface over the other's,
// each placed midway between the surfaces with depth = height of A - height of B. `incident`:
// vertices of the side against the reference face besides its feature, each a point where it
// lies over the face.
void featureContacts(const Feature& fa, const Feature& fb, Reference reference, const std::vector<Vec3>& incident,
                     const std::vector<Vec3>& incidentFace, const Vec3& n, std::vector<ContactPoint>& out) {
  out.clear();
  const auto emit = [&](const Vec3& p, double ha, double hb) {
    out.push_back({p + n * (0.5 * (ha + hb) - n.dot(p)), ha - hb});
  };
  const std::size_t na = fa.hull.size(), nb = fb.hull.size();
  if (reference != Reference::None) {
    const bool refIsA = reference == Reference::A;
    const Feature& ref = refIsA ? fa : fb;
    thread_local std::vector<Vec3> clipped;
    clipToPrism(refIsA ? fb.hull : fa.hull, ref.hull, n, clipped);
    for (const Vec3& p : incident) {
      if (insidePrism(p, ref.hull, n)) clipped.push_back(p);
    }
    if (incidentFace.size() >= 3) {
      thread_local std::vector<Vec3> face;
      clipToPrism(incidentFace, ref.hull, n, face);
      clipped.insert(clipped.end(), face.begin(), face.end());
    }
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

// The incident face (Box3D's b3FindIncidentFace, manifold.c): of the faces of `hull` through
// every vertex of its support feature `feature` (a vertex or an edge, posed as `vertices`), the
// one most against the reference normal `towards` (its outward normal . towards least), as the
// outline of its vertices seen along n, into `out`; empty when the hull knows no faces.
void incidentFace(const PosedFaces* hull, const std::vector<Vec3>& vertices, const Feature& feature, const Vec3& towards,
                  std::vector<Vec3>& out) {
  out.clear();
  if (hull == nullptr || hull->planes == nullptr || feature.hull.empty()) return;
  const FacePlanes& f = *hull->planes;
  const Vec3 local = hull->rotation.transpose() * towards;
  thread_local std::vector<Vec3> ends, near;
  ends.clear();
  for (const Vec3& p : feature.hull) ends.push_back(hull->rotation.transpose() * (p - hull->position));
  std::size_t best = f.normals.size();
  for (std::size_t k = 0; k < f.normals.size(); ++k) {
    const bool through = std::all_of(ends.begin(), ends.end(), [&](const Vec3& p) {
      return std::abs(f.normals[k].dot(p) - f.offsets[k]) <= kOnFaceTolerance;
    });
    if (through && (best == f.normals.size() || f.normals[k].dot(local) < f.normals[best].dot(local))) best = k;
  }
  if (best == f.normals.size()) return;
  const Vec3 normal = hull->rotation * f.normals[best];
  const double offset = f.offsets[best] + normal.dot(hull->position);
  near.clear();
  for (const Vec3& p : vertices) {
    if (std::abs(normal.dot(p) - offset) <= kOnFaceTolerance) near.push_back(p);
  }
  planarConvexHull(near, towards, kFeatureHullTolerance, out);
}

// `depth` [m]: the pair's penetration along n (EPA's), or minus its distance when apart.
// facesA, facesB: the hulls' faces where known (else null), for the incident face.
ContactManifold featureManifold(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& n,
                                double margin, double tolerance, double depth, const PosedFaces* facesA = nullptr,
                                const PosedFaces* facesB = nullptr) {
  thread_local Feature fa, fb;
  thread_local std::vector<ContactPoint> candidates;
  thread_local std::vector<Vec3> incident, face;
  supportFeature(a, n, n, tolerance, fa);
  supportFeature(b, -n, n, tolerance, fb);
  const Reference reference = fa.hull.size() >= 3 ? Reference::A : fb.hull.size() >= 3 ? Reference::B : Reference::None;
  // Against a reference face, the other side is its incident part: every vertex of it within the
  // speculative margin of the face's plane, depth + margin beyond its own extreme (Box3D's hull
  // manifold, convex_manifold.c b3BuildFaceAContact, keeps the clipped incident face's points up
  // to B3_SPECULATIVE_DISTANCE above the reference plane). Only the vertices within `tolerance`
  // of the extreme gave one point for a tilted face or an edge pressed into a face, about which
  // the pair turned deeper into each other (issue 56, Box3D's convex pile). Its vertices are
  // taken, not a clip of their outline, whose edges are chords through the body, not its
  // surface; the feature's own clip still gives the points along the face's rim.
  const double reach = std::max(tolerance, depth + margin);
  incident.clear();
  if (reference == Reference::A && fb.hull.size() < 3) nearExtreme(b, -n, reach, incident);
  if (reference == Reference::B && fa.hull.size() < 3) nearExtreme(a, n, reach, incident);
  // And, as Box3D builds its face contact (convex_manifold.c b3BuildFaceAContact), the other
  // side's incident face clipped to the reference face's prism: a vertex or an edge pressed
  // into a small face has its neighbours outside the prism, and the face's outline crossing the
  // prism gives the points around it that hold the pair from turning about the one point (issue
  // 56: Box3D's convex pile, hulls of 32 points whose faces are triangles).
  face.clear();
  if (reference == Reference::A && fb.hull.size() < 3) incidentFace(facesB, b, fb, n, face);
  if (reference == Reference::B && fa.hull.size() < 3) incidentFace(facesA, a, fa, -n, face);
  featureContacts(fa, fb, reference, incident, face, n, candidates);
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

namespace {

// The SAT separation along the face of `hull` whose outward normal is most along `direction`:
// how far the other set's nearest vertex lies outside that face's plane (< 0 inside) [m], and
// the face's world normal.
std::pair<double, Vec3> faceSeparation(const PosedFaces& hull, const Vec3& direction, const std::vector<Vec3>& other) {
  const FacePlanes& f = *hull.planes;
  const Vec3 local = hull.rotation.transpose() * direction;
  std::size_t best = 0;
  for (std::size_t k = 1; k < f.normals.size(); ++k) {
    if (f.normals[k].dot(local) > f.normals[best].dot(local)) best = k;
  }
  const Vec3 normal = hull.rotation * f.normals[best];
  const double offset = f.offsets[best] + normal.dot(hull.position);
  double separation = std::numeric_limits<double>::infinity();
  for (const Vec3& p : other) separation = std::min(separation, normal.dot(p) - offset);
  return {separation, normal};
}

// An empty manifold gets the deepest (or closest) pair's midpoint.
ConvexContact finish(ConvexContact out) {
  if (out.manifold.count == 0) out.manifold.add(0.5 * (out.pointA + out.pointB), out.overlap ? out.depth : -out.distance);
  return out;
}

ConvexContact collideGeneral(const SupportMap& supportA, const std::vector<Vec3>& a, const PosedFaces* facesA,
                             const SupportMap& supportB, const std::vector<Vec3>& b, const PosedFaces* facesB,
                             double margin, double featureTolerance) {
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
  double separation = out.overlap ? -out.depth : out.distance;
  // Box3D's preference for a face (kFaceAxisPreference): the face of A most along n, or of B most
  // against it, when it separates the hulls nearly as well as EPA's axis. Only the manifold's
  // normal and depth change; the contact's reported depth and points stay EPA's.
  Vec3 faceNormal = n;
  double faceSeparationBest = -std::numeric_limits<double>::infinity();
  if (facesA != nullptr && facesA->planes != nullptr && !facesA->planes->normals.empty()) {
    const auto [s, normal] = faceSeparation(*facesA, n, b);
    if (s > faceSeparationBest) {
      faceSeparationBest = s;
      faceNormal = normal;
    }
  }
  if (facesB != nullptr && facesB->planes != nullptr && !facesB->planes->normals.empty()) {
    const auto [s, normal] = faceSeparation(*facesB, -n, a);
    if (s > faceSeparationBest) {
      faceSeparationBest = s;
      faceNormal = -normal;
    }
  }
  // The face's manifold stands if its deepest point is within the preference of EPA's depth, as
  // Box3D compares the edge axis with the clipped points' separation: a small reference face
  // whose prism misses where the hulls overlap most clips away the depth (measured: points 3 mm
  // deep for hulls 0.26 m into each other), and the pair would go on pressing in.
  const double preference = kFaceAxisPreference + kDeepFaceAxisPreference * std::max(-separation, 0.0);
  if (faceSeparationBest >= separation - preference) {
    out.manifold = featureManifold(a, b, faceNormal, margin, featureTolerance, -faceSeparationBest, facesA, facesB);
    if (out.manifold.count > 0 && -out.manifold.maxDepth() <= separation + preference) return finish(out);
  }
  out.manifold = featureManifold(a, b, n, margin, featureTolerance, -separation, facesA, facesB);
  return finish(out);
}

}  // namespace

ConvexContact collideConvex(const SupportMap& supportA, const std::vector<Vec3>& a, const SupportMap& supportB,
                            const std::vector<Vec3>& b, double margin, double featureTolerance) {
  return collideGeneral(supportA, a, nullptr, supportB, b, nullptr, margin, featureTolerance);
}

ConvexContact collideHulls(const SupportMap& supportA, const std::vector<Vec3>& a, const PosedFaces& facesA,
                           const SupportMap& supportB, const std::vector<Vec3>& b, const PosedFaces& facesB,
                           double margin) {
  return collideGeneral(supportA, a, &facesA, supportB, b, &facesB, margin, kSupportFeatureTolerance);
}

}  // namespace rbsim
