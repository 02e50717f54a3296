#pragma once
// Axis-aligned bounding box in world coordinates: the broad phase's bounding volume (seed 004
// "Bounding volumes": AABB). Intervals are closed, so touching boxes overlap.
#include <limits>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());   // [m]
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());  // [m]

  bool empty() const { return (min.array() > max.array()).any(); }
  bool overlaps(const Aabb& o) const {
    return (min.array() <= o.max.array()).all() && (o.min.array() <= max.array()).all();
  }
  bool contains(const Vec3& p) const { return (min.array() <= p.array()).all() && (p.array() <= max.array()).all(); }
  void grow(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void grow(const Aabb& o) {
    min = min.cwiseMin(o.min);
    max = max.cwiseMax(o.max);
  }
  Aabb inflated(double margin) const { return {min.array() - margin, max.array() + margin}; }
  Vec3 centre() const { return 0.5 * (min + max); }
  Vec3 extents() const { return max - min; }

  static Aabb of(const std::vector<Vec3>& points) {
    Aabb box;
    for (const Vec3& p : points) box.grow(p);
    return box;
  }
};

}  // namespace rbsim
