// The two time integrators of soft bodies (engine/include/rbsim/soft/soft_body.h).
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/soft/soft_body.h"

namespace rbsim {

namespace {

double dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i].dot(b[i]);
  return sum;
}

}  // namespace

void SoftBody::stepSymplectic(double dt, const Vec3& gravity) {
  // Semi-implicit Euler: the new velocity moves the nodes, as for rigid bodies.
  internalForces(f_);
  for (const Vec3& f : f_) {
    if (!f.allFinite()) throwNonFinite("the internal forces (elastic and damping)", dt);
  }
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (pinned_[i]) continue;
    v_[i] += dt * (f_[i] / m_[i] + gravity);
    x_[i] += dt * v_[i];
  }
}

void SoftBody::stepBackwardEuler(double dt, const Vec3& gravity) {
  // Baraff and Witkin, "Large Steps in Cloth Simulation" (1998), eq. 15: one Newton step of
  // backward Euler, (M - dt df/dv - dt^2 df/dx) dv = dt (f_0 + dt df/dx v_0 + M g), solved by
  // conjugate gradients with the mass as preconditioner. df/dx and df/dv are never formed: CG
  // needs only their products with a vector (forceDifferential). Pinned nodes are filtered out.
  const std::size_t n = x_.size();
  internalForces(f_);
  linearize();
  zero_.assign(n, Vec3::Zero());
  q_.resize(n);
  std::vector<Vec3>& scaledVelocity = z_;
  scaledVelocity.resize(n);
  for (std::size_t i = 0; i < n; ++i) scaledVelocity[i] = dt * v_[i];
  forceDifferential(scaledVelocity, zero_, q_);  // dt df/dx v_0
  r_.resize(n);
  for (std::size_t i = 0; i < n; ++i) r_[i] = pinned_[i] ? Vec3::Zero() : Vec3(dt * (f_[i] + q_[i] + m_[i] * gravity));

  const auto apply = [&](const std::vector<Vec3>& w, std::vector<Vec3>& out) {
    // A w = M w - dt (df/dx (dt w) + df/dv w)
    for (std::size_t i = 0; i < n; ++i) scaledVelocity[i] = dt * w[i];
    forceDifferential(scaledVelocity, w, out);
    for (std::size_t i = 0; i < n; ++i) out[i] = pinned_[i] ? Vec3::Zero() : Vec3(m_[i] * w[i] - dt * out[i]);
  };

  dv_.assign(n, Vec3::Zero());
  std::vector<Vec3>& precond = preconditioned_;
  precond.resize(n);
  for (std::size_t i = 0; i < n; ++i) precond[i] = r_[i] / m_[i];
  p_ = precond;
  double rz = dot(r_, precond);
  const double rhsNorm = std::sqrt(dot(r_, r_));
  // A NaN right-hand side would end CG at once with dv = 0: the body would hang still, silently.
  if (!std::isfinite(rhsNorm)) throwNonFinite("the internal forces (elastic and damping)", dt);
  lastIterations_ = 0;
  for (int k = 0; k < kConjugateGradientMaxIterations && std::sqrt(dot(r_, r_)) > kConjugateGradientTolerance * rhsNorm; ++k) {
    apply(p_, q_);
    const double curvature = dot(p_, q_);
    if (std::isnan(curvature) || std::isinf(curvature)) throwNonFinite("the implicit step's force differentials", dt);
    if (!(curvature > 0.0)) break;  // the linearised system is not positive definite here
    const double alpha = rz / curvature;
    for (std::size_t i = 0; i < n; ++i) {
      dv_[i] += alpha * p_[i];
      r_[i] -= alpha * q_[i];
      precond[i] = r_[i] / m_[i];
    }
    const double rzNext = dot(r_, precond);
    const double beta = rzNext / rz;
    rz = rzNext;
    for (std::size_t i = 0; i < n; ++i) p_[i] = precond[i] + beta * p_[i];
    lastIterations_ = k + 1;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (pinned_[i]) continue;
    v_[i] += dv_[i];
    x_[i] += dt * v_[i];
  }
}

}  // namespace rbsim
