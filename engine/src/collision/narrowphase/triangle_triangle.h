#pragma once
// Triangle-triangle intersection: Moller, "A Fast Triangle-Triangle Intersection Test", JGT 1997
// (seed 004 "Triangle intersection"): reject by each triangle's plane, then overlap the two
// intervals the triangles cut from the line where the planes meet; coplanar triangles by 2D edge
// and containment tests.
#include "rbsim/math/types.h"

namespace rbsim {

// A vertex closer to the other triangle's plane than this fraction of the longest edge of the two
// triangles [1], times that triangle's L^2 / |N| (longest edge squared over twice its area: how
// poorly a sliver's normal is determined), counts as on the plane (Moller's EPSILON, made
// scale-free and aware of slivers).
inline constexpr double kTriTriPlaneRelTolerance = 1e-12;

struct TriTriResult {
  bool intersect = false;
  bool coplanar = false;    // both triangles in one plane (within the tolerance)
  bool degenerate = false;  // a triangle had zero area and was tested as a segment
  // The intersection segment when intersect && !coplanar && !degenerate (a point when touching).
  bool hasSegment = false;
  Vec3 segment[2] = {Vec3::Zero(), Vec3::Zero()};  // [m]
};

// Closed triangles: touching at a vertex or along an edge counts as intersecting.
TriTriResult triangleTriangleIntersection(const Vec3& a0, const Vec3& a1, const Vec3& a2,
                                          const Vec3& b0, const Vec3& b1, const Vec3& b2);

inline bool trianglesIntersect(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0,
                               const Vec3& b1, const Vec3& b2) {
  return triangleTriangleIntersection(a0, a1, a2, b0, b1, b2).intersect;
}

}  // namespace rbsim
