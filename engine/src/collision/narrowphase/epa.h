#pragma once
// EPA, the Expanding Polytope Algorithm (van den Bergen, "Proximity Queries and Penetration Depth
// Computation on 3D Game Objects", GDC 2001): grows GJK's terminating simplex into a polytope
// inside A - B until its face nearest the origin is on the boundary of A - B. That face's normal
// and distance are the penetration normal and depth (the shortest translation separating the
// hulls).
#include <vector>

#include "collision/narrowphase/gjk.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Converged when the support point along the nearest face's normal is no further than this
// beyond the face [m]: the depth is then within this of the true penetration depth.
inline constexpr double kEpaTolerance = 1e-9;
// A new support point must leave the affine hull of the start simplex by this much [m] to blow a
// point, segment or triangle up into a tetrahedron.
inline constexpr double kEpaBlowUpTolerance = 1e-9;
inline constexpr int kEpaMaxIterations = 128;

struct EpaResult {
  // False when A - B is flat (no tetrahedron fits in it) or a set is empty; the rest is then
  // meaningless.
  bool valid = false;
  Vec3 normal = Vec3::UnitY();  // unit, from A towards B: moving B by depth * normal separates
  double depth = 0.0;           // [m], >= 0 up to rounding
  Vec3 pointA = Vec3::Zero();   // deepest point of A inside B [m]
  Vec3 pointB = Vec3::Zero();   // deepest point of B inside A [m]; pointA - pointB = depth * normal
  // The support point along the normal was within kEpaTolerance of the face. False when the
  // iteration or face cap was hit or rounding stopped the expansion: the depth is then a lower
  // bound and the normal approximate.
  bool converged = false;
  int iterations = 0;
};

// `start` is GJK's terminating simplex for overlapping hulls (any size 1..4: fewer than 4 points,
// as when the hulls only touch, are blown up to a tetrahedron by support points).
EpaResult epa(const SupportMap& a, const SupportMap& b, const GjkSimplex& start);
EpaResult epa(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const GjkSimplex& start);  // empty: invalid

}  // namespace rbsim
