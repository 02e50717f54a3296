#include "dynamics/friction_law.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace rbsim {

namespace {

// Newton's iterations for the static limit's lambda: from lambda = 0 they increase monotonically
// to the root, within 1e-12 in a few; this caps them.
constexpr int kTrustRegionIterations = 30;  // [iterations]

// The impulse on the circle of radius `radius` nearest `sticking` in the metric of K_TT (the
// least kinetic energy left; a radial cut of the coupled 2x2 solve let a box creep off a 30
// degree incline at 5 mm/s a step), j = (K_TT + lambda 1)^-1 K_TT j_stick with lambda >= 0 where
// |j| = radius: the trust-region step (More and Sorensen 1983), by Newton's method on
// 1/|j(lambda)| - 1/radius in K_TT's eigenbasis.
Eigen::Vector2d staticLimit(const Eigen::Matrix2d& factor, const Eigen::Vector2d& sticking, double radius) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
  eigen.computeDirect(factor);
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
  return radius * (eigen.eigenvectors() * limited).normalized();
}

}  // namespace

FrictionImpulse seed000Friction(const FrictionPoint& p) {
  FrictionImpulse out;
  Eigen::Matrix2d factor;  // K_TT
  factor << 1.0 / p.tangentMass[0], p.coupling, p.coupling, 1.0 / p.tangentMass[1];
  // Sticking: the impulse that leaves no tangential relative velocity (seed 000 "Friction").
  const Eigen::Vector2d sticking = p.accumulated - factor.inverse() * p.slip;
  if (sticking.norm() <= p.staticFriction * p.normalImpulse) {
    out.total = sticking;
    out.sticking = true;
    return out;
  }
  if (p.sliding && p.slip.squaredNorm() > 0.0) {  // kinetic: -mu_k j_n T
    out.total = -(p.kineticFriction * p.normalImpulse) * p.slip.normalized();
    return out;
  }
  const double radius = p.staticFriction * p.normalImpulse;  // static, at its limit
  if (radius > 0.0) out.total = staticLimit(factor, sticking, radius);
  return out;
}

}  // namespace rbsim
