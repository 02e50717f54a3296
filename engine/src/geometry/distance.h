#pragma once
// Seed 004's distance tests (point-point, point-edge, point-face) with the closest point and the
// feature it lies on, plus segment-segment closest points for edge-edge contacts. Point-face uses
// Voronoi regions (Ericson, Real-Time Collision Detection §5.1.5); segment-segment is §5.1.9.
#include <array>

#include "rbsim/math/types.h"

namespace rbsim {

// Below this length [m] a segment is treated as the point at its start (its direction is noise).
inline constexpr double kDegenerateSegmentLength = 1e-12;
// A triangle whose |ab x ac| is below this fraction of its longest edge squared [1] is treated as
// the three segments it degenerates to: the face region's barycentric division would be 0/0.
inline constexpr double kDegenerateTriangleRatio = 1e-12;

// Seed 004 "Point to point": d = |p0 - p1| [m].
double pointPointDistance(const Vec3& p0, const Vec3& p1);

enum class SegmentFeature { Start, End, Interior };

struct PointSegmentResult {
  Vec3 closest = Vec3::Zero();  // on the segment [m]
  double t = 0.0;               // closest = a + t (b - a), t in [0, 1]
  double distance = 0.0;        // [m]
  SegmentFeature feature = SegmentFeature::Start;
};

// Seed 004 "Point-Edge": the closest point of segment ab to p.
PointSegmentResult closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b);

enum class TriangleFeature { VertexA, VertexB, VertexC, EdgeAB, EdgeBC, EdgeCA, Face };

struct PointTriangleResult {
  Vec3 closest = Vec3::Zero();                 // on the triangle [m]
  std::array<double, 3> barycentric{1, 0, 0};  // weights of a, b, c: closest = sum w_i v_i
  double distance = 0.0;                       // [m]
  TriangleFeature feature = TriangleFeature::VertexA;
};

// Seed 004 "Point-face": the closest point of triangle abc to p and the Voronoi region (vertex,
// edge or face) containing p. A degenerate (zero-area) triangle answers with the closest of its
// three edges, so the result is never NaN.
PointTriangleResult closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

struct SegmentSegmentResult {
  Vec3 closest1 = Vec3::Zero();  // on segment 1 = p1 + s (q1 - p1) [m]
  Vec3 closest2 = Vec3::Zero();  // on segment 2 = p2 + t (q2 - p2) [m]
  double s = 0.0, t = 0.0;       // in [0, 1]
  double distance = 0.0;         // [m]
};

// Closest points of segments p1q1 and p2q2. Parallel segments have a continuum of closest pairs;
// one of them is returned (the one with s = 0 where that is possible).
SegmentSegmentResult closestPointsSegmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2,
                                                 const Vec3& q2);

}  // namespace rbsim
