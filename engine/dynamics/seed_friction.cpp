#include "rbsim/dynamics/seed_friction.h"

#include <Eigen/LU>

namespace rbsim {

SeedFriction seedFriction(const Mat3& totalFactor, const Vec3& relativeVelocity, const Vec3& normal, const Vec3& t1,
                          const Vec3& t2, const Vec3& accumulated, double normalImpulse, double staticFriction,
                          double kineticFriction, bool sliding) {
  SeedFriction out;
  Eigen::Matrix<double, 3, 2> basis;
  basis << t1, t2;
  const Eigen::Matrix2d tangentFactor = basis.transpose() * totalFactor * basis;  // K_TT
  const Eigen::Vector2d slip = basis.transpose() * relativeVelocity;              // u_rel,T
  // Sticking: the impulse that leaves no tangential relative velocity (seed 000 "Friction").
  const Eigen::Vector2d sticking = basis.transpose() * accumulated - tangentFactor.inverse() * slip;
  if (sticking.norm() <= staticFriction * normalImpulse) {
    out.total = basis * sticking;
    out.sticking = true;
    return out;
  }
  if (sliding && slip.squaredNorm() > 0.0) {  // kinetic: -mu_k j_n T
    out.total = -(kineticFriction * normalImpulse) * (basis * slip.normalized());
    return out;
  }
  // Static at its limit: the impulse on the circle of radius mu_s j_n nearest the sticking one in
  // the metric of K_TT, j = (K_TT + lambda 1)^-1 K_TT j_stick with lambda >= 0 found by bisection
  // (the trust-region step): the change of kinetic energy it leaves is the least.
  const double radius = staticFriction * normalImpulse;
  const Eigen::Vector2d target = tangentFactor * sticking;
  const auto at = [&](double lambda) {
    return Eigen::Vector2d((tangentFactor + lambda * Eigen::Matrix2d::Identity()).inverse() * target);
  };
  double low = 0.0, high = tangentFactor.trace();
  while (at(high).norm() > radius && high < 1e12 * tangentFactor.trace()) high *= 2.0;
  for (int i = 0; i < 50; ++i) {
    const double middle = 0.5 * (low + high);
    (at(middle).norm() > radius ? low : high) = middle;
  }
  const Eigen::Vector2d limited = at(high);
  out.total = basis * (limited.norm() > 0.0 ? Eigen::Vector2d(radius * limited.normalized()) : limited);
  return out;
}

}  // namespace rbsim
