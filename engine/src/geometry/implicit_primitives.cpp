#include "geometry/implicit_primitives.h"

#include <algorithm>
#include <cmath>

namespace rbsim {

namespace {
// |(a, b)| without std::hypot's care for overflow, which costs 70% of evaluating a tree of tori
// (perf, bench/csg_stress.py): coordinates here are within kMaxCoordinate (1e6 m), so a^2 + b^2
// is far from overflow and underflow only loses what is below rounding of the distance anyway.
double length2(double a, double b) { return std::sqrt(a * a + b * b); }
}  // namespace

double TorusSurface::phi(const Vec3& p) const {
  const double ring = length2(p.x(), p.z()) - majorRadius;
  return length2(ring, p.y()) - minorRadius;
}

double CapsuleSurface::phi(const Vec3& p) const {
  const Vec3 nearest(0.0, std::clamp(p.y(), -halfLength, halfLength), 0.0);
  return (p - nearest).norm() - radius;
}

double CylinderSurface::phi(const Vec3& p) const {
  const double dx = length2(p.x(), p.z()) - radius, dy = std::abs(p.y()) - halfHeight;
  return std::min(std::max(dx, dy), 0.0) + length2(std::max(dx, 0.0), std::max(dy, 0.0));
}

}  // namespace rbsim
