#include "geometry/implicit_surface.h"

#include <algorithm>

namespace rbsim {

double SphereSurface::phi(const Vec3& p) const { return p.norm() - radius; }

Vec3 SphereSurface::gradient(const Vec3& p) const {
  const double r = p.norm();
  return r > 0.0 ? Vec3(p / r) : Vec3::UnitX();
}

double BoxSurface::phi(const Vec3& p) const {
  const Vec3 q = p.cwiseAbs() - halfExtents;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

Vec3 BoxSurface::gradient(const Vec3& p) const {
  const Vec3 q = p.cwiseAbs() - halfExtents;
  const Vec3 sign = p.unaryExpr([](double x) { return x < 0.0 ? -1.0 : 1.0; });
  const Vec3 outside = q.cwiseMax(0.0);
  const double outsideLength = outside.norm();
  if (outsideLength > 0.0) return sign.cwiseProduct(outside) / outsideLength;
  Eigen::Index axis = 0;
  q.maxCoeff(&axis);
  Vec3 n = Vec3::Zero();
  n[axis] = sign[axis];
  return n;
}

double EllipsoidSurface::phi(const Vec3& p) const {
  const Vec3 dp = p.cwiseQuotient(radii);
  const double k0 = dp.norm();
  const double k1 = dp.cwiseQuotient(radii).norm();
  if (k1 == 0.0) return -radii.minCoeff();  // the centre: the nearest surface point is the
                                             // end of the shortest semi-axis
  return k0 * (k0 - 1.0) / k1;
}

Vec3 EllipsoidSurface::gradient(const Vec3& p) const {
  const Vec3 d1p = p.cwiseQuotient(radii);       // D p
  const Vec3 d2p = d1p.cwiseQuotient(radii);     // D^2 p
  const Vec3 d4p = d2p.cwiseQuotient(radii).cwiseQuotient(radii);  // D^4 p
  const double k0 = d1p.norm(), k1 = d2p.norm();
  if (k1 == 0.0) return Vec3::UnitX();
  // grad k0 = D^2 p / k0 and grad k1 = D^4 p / k1; phi = k0 (k0 - 1) / k1 by the quotient rule.
  const Vec3 gradK0 = d2p / k0, gradK1 = d4p / k1;
  return ((2.0 * k0 - 1.0) * gradK0 * k1 - k0 * (k0 - 1.0) * gradK1) / (k1 * k1);
}

}  // namespace rbsim
