#pragma once
// The infinite static plane, the sixth shape (shapes/shape.h): the World's, never a body's
// (World::addPlane). Its exact queries are a signed distance and a ray hit.
#include <limits>

#include "rbsim/math/types.h"

namespace rbsim {

// n . p = offset, solid on the side -n (the ground y = 0 has n = +y).
struct Plane {
  Vec3 normal = Vec3::UnitY();  // unit [1]
  double offset = 0.0;          // [m]
  double signedDistance(const Vec3& p) const { return normal.dot(p) - offset; }
  // The ray parameter t >= 0 at which origin + t direction meets the plane from its open side,
  // or infinity when it does not (parallel, leaving, or starting inside).
  double rayHit(const Vec3& origin, const Vec3& direction) const {
    const double approach = normal.dot(direction), distance = signedDistance(origin);
    if (!(approach < 0.0) || distance < 0.0) return std::numeric_limits<double>::infinity();
    return distance / -approach;
  }
};

}  // namespace rbsim
