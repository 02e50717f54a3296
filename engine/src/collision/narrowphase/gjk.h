#pragma once
// GJK (Gilbert, Johnson, Keerthi 1988; van den Bergen 1999 "A fast and robust GJK implementation
// for collision detection of convex objects"; Ericson §9.5) on the support mappings of vertex
// sets. A set stands for its convex hull: support(d) = argmax_i d . p_i, so a non-convex mesh is
// treated as its convex hull. Distance and closest points when the hulls are apart; overlap (and
// the terminating simplex, for EPA) when they touch or intersect.
#include <array>
#include <cstddef>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

// Stop when the gap between GJK's upper bound |v| and lower bound v.w / |v| on the distance is
// below this [m].
inline constexpr double kGjkDistanceTolerance = 1e-10;
// A closest point of A - B this near the origin [m] means the hulls touch or overlap.
inline constexpr double kGjkOverlapTolerance = 1e-10;
// More iterations than this only happen when rounding stops progress; the best v so far is kept.
inline constexpr int kGjkMaxIterations = 64;

// A point of the Minkowski difference A - B and the two vertices it came from.
struct SupportPoint {
  Vec3 w = Vec3::Zero();  // a - b [m]
  Vec3 a = Vec3::Zero();  // vertex of A [m]
  Vec3 b = Vec3::Zero();  // vertex of B [m]
};

struct GjkSimplex {
  std::array<SupportPoint, 4> points{};
  int size = 0;
};

struct GjkResult {
  bool overlap = false;    // the hulls touch or intersect; distance is then 0
  double distance = 0.0;   // [m]; +infinity when a set is empty
  Vec3 pointA = Vec3::Zero();  // closest point of hull A [m]
  Vec3 pointB = Vec3::Zero();  // closest point of hull B [m]
  GjkSimplex simplex;      // the terminating simplex (EPA's start when overlap)
  int iterations = 0;
};

// Index of the vertex of `points` furthest along `direction` (the first one on ties).
std::size_t supportIndex(const std::vector<Vec3>& points, const Vec3& direction);

// A convex set as GJK and EPA see it (van den Bergen 2003, ch. 4): its support mapping, the point
// of the set furthest along a direction, world frame. A shape answers it in its own way
// (shapes/shape.h: a formula, a scan, a climb over a hull's vertex graph).
class SupportMap {
 public:
  virtual ~SupportMap() = default;
  virtual Vec3 support(const Vec3& direction) const = 0;
  virtual Vec3 anyPoint() const = 0;  // where GJK starts: a point of the set
};

// The convex hull of a vertex set, by scanning every vertex.
class PointSetSupport final : public SupportMap {
 public:
  explicit PointSetSupport(const std::vector<Vec3>& points) : points_(points) {}
  Vec3 support(const Vec3& direction) const override { return points_[supportIndex(points_, direction)]; }
  Vec3 anyPoint() const override { return points_[0]; }

 private:
  const std::vector<Vec3>& points_;
};

// The support point of A - B in `direction`: support_A(d) - support_B(-d).
SupportPoint minkowskiSupport(const SupportMap& a, const SupportMap& b, const Vec3& direction);
SupportPoint minkowskiSupport(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& direction);

// The point of the simplex's hull closest to the origin; the simplex is reduced to the smallest
// subset holding it (Ericson §9.5.2: the sub-simplex whose Voronoi region contains the origin),
// with the barycentric weights of that point in lambda.
Vec3 closestToOrigin(GjkSimplex& s, std::array<double, 4>& lambda);

GjkResult gjk(const SupportMap& a, const SupportMap& b);
GjkResult gjk(const std::vector<Vec3>& a, const std::vector<Vec3>& b);  // empty sets: +infinity apart

}  // namespace rbsim
