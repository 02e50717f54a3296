#include "dynamics/seed_friction.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace rbsim {

namespace {

// Newton's iterations for the static limit's lambda: from lambda = 0 they increase monotonically
// to the root, within 1e-12 in a few; this caps them.
constexpr int kTrustRegionIterations = 30;  // [iterations]

}  // namespace

SeedFriction seedFriction(const Mat3& totalFactor, const Vec3& relativeVelocity, const Vec3& t1, const Vec3& t2,
                          const Vec3& accumulated, double normalImpulse, double staticFriction,
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
  // the metric of K_TT (the least kinetic energy left; a radial cut of the coupled 2x2 solve let a
  // box creep off a 30 degree incline at 5 mm/s a step), j = (K_TT + lambda 1)^-1 K_TT j_stick with
  // lambda >= 0 where |j| = mu_s j_n: the trust-region step (More and Sorensen 1983), by Newton's
  // method on 1/|j(lambda)| - 1/radius in K_TT's eigenbasis.
  const double radius = staticFriction * normalImpulse;
  if (!(radius > 0.0)) return out;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
  eigen.computeDirect(tangentFactor);
  const Eigen::Vector2d k = eigen.eigenvalues();
  const Eigen::Vector2d c = eigen.eigenvectors().transpose() * sticking;
  double lambda = 0.0;
  for (int i = 0; i < kTrustRegionIterations; ++i) {
    double squared = 0.0, slope = 0.0;
    for (int e = 0; e < 2; ++e) {
      const double term = k[e] * c[e] / (k[e] + lambda);
      squared += term * term;
      slope += term * term / (k[e] + lambda);
    }
    const double norm = std::sqrt(squared);
    const double step = (1.0 / radius - 1.0 / norm) / (slope / (squared * norm));
    lambda += step;
    if (std::abs(step) <= 1e-12 * (lambda + k.maxCoeff())) break;
  }
  Eigen::Vector2d limited;
  for (int e = 0; e < 2; ++e) limited[e] = k[e] * c[e] / (k[e] + lambda);
  limited = eigen.eigenvectors() * limited;
  out.total = basis * Eigen::Vector2d(radius * limited.normalized());
  return out;
}

}  // namespace rbsim
