#pragma once
// Contact polygons: Sutherland-Hodgman clipping (Sutherland & Hodgman, "Reentrant Polygon
// Clipping", CACM 1974) of a convex polygon by a half-space, and the convex hull of points as
// seen along a direction (Andrew's monotone chain, 1979), both in 3D.
#include <cstddef>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

// The part of the convex polygon (vertices in order; 1 vertex is a point, 2 a segment) where
// normal . p <= offset. New vertices lie on the polygon's edges, so they keep its surface.
std::vector<Vec3> clipByHalfSpace(const std::vector<Vec3>& polygon, const Vec3& normal, double offset);
// The same clip without allocating: the `count` vertices at `polygon` into `out`, which has room
// for count + 1 (clipping a convex polygon adds at most one vertex). Returns the vertices written.
std::size_t clipByHalfSpace(const Vec3* polygon, std::size_t count, const Vec3& normal, double offset, Vec3* out);

// The vertices of the convex hull of `points` projected along unit `axis`, counter-clockwise
// about it. Each returned vertex is one of the input points (unprojected). Vertices within
// `tolerance` [m] of the line through their neighbours are dropped, so the result has 1 point
// (all within tolerance of one point), 2 (all within tolerance of a segment) or at least 3.
std::vector<Vec3> planarConvexHull(const std::vector<Vec3>& points, const Vec3& axis, double tolerance);
// The same into `out` (not `points`), with the working arrays kept per thread: no allocation once
// the buffers have grown.
void planarConvexHull(const std::vector<Vec3>& points, const Vec3& axis, double tolerance, std::vector<Vec3>& out);

// A unit vector perpendicular to unit n, and n x it: a right-handed basis of n's plane.
void planeBasis(const Vec3& n, Vec3& u, Vec3& v);

}  // namespace rbsim
