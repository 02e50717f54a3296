#pragma once
// Exact solutions of torque-free rigid-body rotation, for checking integrators.
// Body axes are principal axes; R(t) is the body-to-world rotation (w_world = R w_body) and all
// angular velocities are body-frame unless named otherwise.
#include "rbsim/math/types.h"

namespace rbsim::reference {

// Jacobi elliptic functions sn, cn, dn of argument u, taking the complementary modulus
// kc = sqrt(1 - k^2) in [0, 1] (AGM / descending Landen, Abramowitz & Stegun 16.4; DLMF 22.20(ii)).
// Taking kc rather than k keeps full precision near the separatrix, where k -> 1.
struct JacobiSnCnDn {
  double sn, cn, dn;
};
JacobiSnCnDn jacobiSnCnDn(double u, double kc);

// Complete elliptic integral of the first kind K = pi / (2 AGM(1, kc)) (DLMF §19.8(i)).
double completeEllipticK(double kc);

// Asymmetric body, moments I1 < I2 < I3 (Landau & Lifshitz, Mechanics §37). With M = |L| and
// E the kinetic energy, the body-frame omega is
//   M^2 > 2 E I2 (spin about axis 3):  w1 = A1 cn(u),  w2 = s A2 sn(u),  w3 = s A3 dn(u)
//   M^2 < 2 E I2 (spin about axis 1):  w1 = s A1 dn(u),  w2 = s A2 sn(u),  w3 = A3 cn(u)
// with u = wp t + u0, s = the sign of the dn component, and A_i, wp, k as in L&L §37 (the second
// case is the first with axes 1 and 3 swapped). The separatrix M^2 = 2 E I2 (which includes a
// pure spin about axis 2) is rejected: its motion is not periodic.
//
// The orientation uses L&L's Euler angles (z-x-z, body to the frame with L along z):
// cos(theta) = L3 / M and tan(psi) = L1 / L2 in closed form from L_body = I w, and
// dphi/dt = M (I1 w1^2 + I2 w2^2) / (I1^2 w1^2 + I2^2 w2^2) (L&L §37), which is integrated
// by adaptive Gauss-Kronrod quadrature (relative tolerance 1e-13) over at most half a period of
// omega; whole half periods add a precomputed increment. It is not an elliptic integral of the
// third kind evaluated in closed form.
class TorqueFreeExact {
 public:
  // Throws std::invalid_argument unless 0 < I1 < I2 < I3, or on the separatrix. omega0 = 0 is
  // allowed: the body stays at R0.
  TorqueFreeExact(const Vec3& moments, const Vec3& omega0, const Mat3& R0 = Mat3::Identity());

  Vec3 omegaBody(double t) const;  // [rad/s], body frame
  Mat3 rotation(double t) const;   // body-to-world; rotation(0) == R0

  // Period of omega_body(t): 4 K(k) / wp [s]. The sn component (axis 2) and the cn component
  // change sign every half period, so for a spin near the intermediate axis (Dzhanibekov) the
  // body flips over every period() / 2 and is back to its initial body-frame omega after
  // period(). The orientation is not periodic in general (phi advances by an irrational angle).
  // For a pure spin about axis 1 or 3 (k = 0, omega constant) this is 2 pi / wp; infinite at rest.
  double period() const { return period_; }
  double modulus() const { return k_; }          // elliptic modulus k in [0, 1)
  bool aboutAxis3() const { return aboutAxis3_; }  // M^2 > 2 E I2

 private:
  double phiRate(double t) const;      // dphi/dt [rad/s]
  double phiIntegral(double t) const;  // integral of phiRate over [0, t], t in [0, period/2]

  Vec3 I_;
  Vec3 amplitude_ = Vec3::Zero();  // A1, A2, A3 >= 0
  double sign_ = 1.0;              // sign of the dn component
  double wp_ = 0.0, u0_ = 0.0, k_ = 0.0, kc_ = 1.0, K_ = 0.0;
  double period_ = 0.0;
  double momentum_ = 0.0;   // M = |L|
  double halfPhi_ = 0.0;    // phi advance over one half period
  bool aboutAxis3_ = true;
  bool atRest_ = false;
  Mat3 frame_ = Mat3::Identity();  // world-fixed frame with L along its z: R = frame Rz(phi) B
};

// Symmetric body I1 = I2 != I3 (Goldstein, Classical Mechanics §5.6; L&L §33): in the body frame
// omega precesses about axis 3 at Omega = (I3 - I1) / I1 * w3 with w3 constant, and in space the
// body rotates about L at |L| / I1: R(t) = Rot(L_hat, |L| t / I1) R0 Rot(e3, -Omega t).
class SymmetricTopExact {
 public:
  // Throws std::invalid_argument unless I1 > 0 and I3 > 0.
  SymmetricTopExact(double I1, double I3, const Vec3& omega0, const Mat3& R0 = Mat3::Identity());

  Vec3 omegaBody(double t) const;
  Mat3 rotation(double t) const;
  double bodyPrecessionRate() const { return Omega_; }  // Omega [rad/s]
  double spacePrecessionRate() const { return spaceRate_; }  // |L| / I1 [rad/s]

 private:
  Vec3 omega0_;
  Mat3 R0_;
  Vec3 axisWorld_ = Vec3::UnitZ();  // L_hat in world
  double Omega_ = 0.0, spaceRate_ = 0.0;
};

// Free fall: x0 + v0 t + g t^2 / 2.
inline Vec3 projectile(const Vec3& x0, const Vec3& v0, const Vec3& g, double t) {
  return x0 + v0 * t + 0.5 * t * t * g;
}

}  // namespace rbsim::reference
