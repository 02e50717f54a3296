#include "geometry/implicit_primitives.h"

#include <algorithm>
#include <cmath>

namespace rbsim {

double TorusSurface::phi(const Vec3& p) const {
  const double ring = std::hypot(p.x(), p.z()) - majorRadius;
  return std::hypot(ring, p.y()) - minorRadius;
}

double CapsuleSurface::phi(const Vec3& p) const {
  const Vec3 nearest(0.0, std::clamp(p.y(), -halfLength, halfLength), 0.0);
  return (p - nearest).norm() - radius;
}

double CylinderSurface::phi(const Vec3& p) const {
  const double dx = std::hypot(p.x(), p.z()) - radius, dy = std::abs(p.y()) - halfHeight;
  return std::min(std::max(dx, dy), 0.0) + std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
}

}  // namespace rbsim
