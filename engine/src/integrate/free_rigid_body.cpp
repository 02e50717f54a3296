#include "rbsim/integrate/free_rigid_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

namespace rbsim {

namespace {

// Double precision throughout (Boost would otherwise promote to long double, 3x slower here for
// no digit we keep), and a NaN rather than an exception on any error: the world's divergence
// check then names the body.
using Elliptic = boost::math::policies::policy<
    boost::math::policies::promote_double<false>,
    boost::math::policies::domain_error<boost::math::policies::errno_on_error>,
    boost::math::policies::overflow_error<boost::math::policies::errno_on_error>,
    boost::math::policies::evaluation_error<boost::math::policies::errno_on_error>>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// |1/a - 1/b| without cancellation beyond the subtraction of the moments themselves [1/(kg m^2)].
double inverseGap(double a, double b) { return std::abs(a - b) / (a * b); }

// A(m): the rotation Rx(theta) Rz(psi) taking m / |m| to e_3, with cos(theta) = m_3 / |m| and
// psi = atan2(m_1, m_2) (Landau & Lifshitz §35's Euler angles with L along the fixed z axis).
// For this choice the remaining angle phi about L obeys L&L's
// dphi/dt = |m| (m_1 w_1 + m_2 w_2) / (m_1^2 + m_2^2). Needs m_3 >= 0; half angles by square
// roots of sums, accurate for every m.
Quat alignmentToAxis3(const Vec3& m) {
  const double g = m.norm();
  const double rho = std::sqrt(m.x() * m.x() + m.y() * m.y());
  const double cosHalfTheta = std::sqrt((g + m.z()) / (2.0 * g));
  const double sinHalfTheta = rho / (2.0 * g * cosHalfTheta);
  double cosHalfPsi = 1.0, sinHalfPsi = 0.0;
  if (rho > 0.0) {
    if (m.y() >= 0.0) {
      cosHalfPsi = std::sqrt((rho + m.y()) / (2.0 * rho));
      sinHalfPsi = m.x() / (2.0 * rho * cosHalfPsi);
    } else {
      sinHalfPsi = std::copysign(std::sqrt((rho - m.y()) / (2.0 * rho)), m.x());
      cosHalfPsi = m.x() / (2.0 * rho * sinHalfPsi);
    }
  }
  // (cos t/2, sin t/2 e_x) (cos p/2, sin p/2 e_z)
  return Quat(cosHalfTheta * cosHalfPsi, sinHalfTheta * cosHalfPsi, -sinHalfTheta * sinHalfPsi,
              cosHalfTheta * sinHalfPsi);
}

// Where the phase is reflected about K (see phaseAt): beyond this fraction of K [1], and at
// epoch when cn u0 < this times |sn u0| [1].
constexpr double kReflectBeyond = 0.5;
constexpr double kReflectBelow = 0.5;

int leviCivita(int a, int b, int c) { return (a - b) * (b - c) * (c - a) / 2; }

// Near the separatrix k -> 1 and the complementary modulus kc = sqrt(1 - k^2) carries the
// digits: K, F and Pi are written as Carlson's symmetric integrals of kc^2 (DLMF 19.25.1,
// 19.25.5, 19.25.14), for amplitudes |phi| <= pi/2 with s = sin(phi), c = cos(phi).
double completeFirstKind(double kc2) { return boost::math::ellint_rf(0.0, kc2, 1.0, Elliptic()); }
double firstKind(double s, double c, double kc2) {
  return s * boost::math::ellint_rf(c * c, c * c + kc2 * s * s, 1.0, Elliptic());
}
// Pi(n; phi | k) = integral dtheta / ((1 - n sin^2) sqrt(1 - k^2 sin^2)), n < 1.
double thirdKind(double n, double s, double c, double kc2) {
  const double c2 = c * c, delta2 = c2 + kc2 * s * s;
  return s * boost::math::ellint_rf(c2, delta2, 1.0, Elliptic()) +
         n / 3.0 * s * s * s * boost::math::ellint_rj(c2, delta2, 1.0, 1.0 - n * s * s, Elliptic());
}
double completeThirdKind(double n, double kc2) {
  return boost::math::ellint_rf(0.0, kc2, 1.0, Elliptic()) +
         n / 3.0 * boost::math::ellint_rj(0.0, kc2, 1.0, 1.0 - n, Elliptic());
}

}  // namespace

FreeRigidBodyFlow::FreeRigidBodyFlow(const Quat& principalToWorld, const Vec3& angularMomentum,
                                     const Vec3& principalMoments)
    : given_(principalToWorld), epoch_(principalToWorld.normalized()), angularMomentum_(angularMomentum), moments_(principalMoments) {
  momentumMagnitude_ = angularMomentum.stableNorm();  // |L| from 1e-160 to 1e158 without under- or overflow
  if (momentumMagnitude_ == 0.0) return;  // Regime::Rest
  const Vec3& I = moments_;
  const Vec3 m = epoch_.conjugate() * angularMomentum;
  // The momentum in units of G: squares of |L| near 1e-160 or 1e155 [kg m^2/s] (moments and
  // spins within the scene's ranges) would under- or overflow; the amplitudes and rate scale back.
  const Vec3 unit = m / momentumMagnitude_;
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&I](int a, int b) { return I[a] < I[b]; });
  const int lo = order[0], mid = order[1], hi = order[2];
  // G^2 - 2 T I_mid = sum m_i^2 (1 - I_mid / I_i): the side of the separatrix. At or above zero
  // the momentum circulates about the major axis, below it about the minor one.
  const double side = unit[lo] * unit[lo] * (1.0 - I[mid] / I[lo]) + unit[hi] * unit[hi] * (1.0 - I[mid] / I[hi]);
  const int c = side >= 0.0 ? hi : lo, a = side >= 0.0 ? lo : hi, b = mid;
  // Signs: m_c >= 0 and m_a >= 0 (a rotation by pi about axis c if not), det = +1.
  const double s3 = m[c] >= 0.0 ? 1.0 : -1.0, s1 = m[a] >= 0.0 ? 1.0 : -1.0;
  const double s2 = s1 * s3 * leviCivita(a, b, c);
  circulationFromPrincipal_.setZero();
  circulationFromPrincipal_(0, a) = s1;
  circulationFromPrincipal_(1, b) = s2;
  circulationFromPrincipal_(2, c) = s3;
  const Vec3 mc = circulationFromPrincipal_ * unit;
  circulationMoments_ = Vec3(I[a], I[b], I[c]);
  const Vec3& Ic = circulationMoments_;

  const double p13 = inverseGap(Ic[0], Ic[2]), p12 = inverseGap(Ic[0], Ic[1]), p23 = inverseGap(Ic[1], Ic[2]);
  // 2T - G^2 / I_3 and G^2 / I_1 - 2T (circulation frame, up to sign), as sums of squares.
  const double d3 = mc[0] * mc[0] * p13 + mc[1] * mc[1] * p23;
  const double d1 = mc[1] * mc[1] * p12 + mc[2] * mc[2] * p13;
  if (d3 == 0.0 || d1 == 0.0 || p23 == 0.0 || (mc[0] == 0.0 && mc[2] == 0.0)) {
    // A spin about a principal axis (the intermediate one too: an unstable equilibrium, which the
    // exact flow keeps), or about any axis of a sphere-like or symmetric inertia that is principal.
    regime_ = Regime::Steady;
    steadyOmega_ = epoch_ * m.cwiseQuotient(I);
    return;
  }
  regime_ = Regime::Elliptic;
  amplitudes_ = momentumMagnitude_ * Vec3(std::sqrt(d3 / p13), std::sqrt(d3 / p23), std::sqrt(d1 / p13));
  // k^2 = d3 p12 / (d1 p23); kc^2 = 1 - k^2 = p13 (m3^2 p23 - m1^2 p12) / (d1 p23), which is
  // |G^2 - 2 T I_2| up to positive factors: zero on the separatrix.
  // Both lie in [0, 1] in exact arithmetic; the bounds only catch rounding at the separatrix.
  k_ = std::sqrt(std::min(1.0, d3 * p12 / (d1 * p23)));
  complementary2_ = std::max(0.0, p13 * (mc[2] * mc[2] * p23 - mc[0] * mc[0] * p12) / (d1 * p23));
  rate_ = (side >= 0.0 ? 1.0 : -1.0) * momentumMagnitude_ * std::sqrt(d1 * p23);
  characteristic_ = -p12 / p23;  // -a3^2 k^2 / a1^2
  const bool periodic = complementary2_ > 0.0;
  quarterPeriodK_ = periodic ? completeFirstKind(complementary2_) : kInfinity;
  completePi_ = periodic ? completeThirdKind(characteristic_, complementary2_) : kInfinity;
  // u0 from (cn u0, sn u0) = (m1 / a1, m2 / a2), with cn u0 >= 0 as m1 >= 0: u0 in [-K, K].
  double c0 = momentumMagnitude_ * mc[0] / amplitudes_[0], s0 = momentumMagnitude_ * mc[1] / amplitudes_[1];
  const double norm0 = std::hypot(c0, s0);
  c0 /= norm0;
  s0 /= norm0;
  if (periodic && c0 < std::abs(s0) * kReflectBelow) {
    // Near u0 = +-K, u0 = +-(K - v0) with sn v0, cn v0 from sn(K - v) = cd v, cn(K - v) = kc sd v.
    const double kc = std::sqrt(complementary2_), d = std::sqrt(complementary2_ + k_ * k_ * c0 * c0);
    u0_ = std::copysign(quarterPeriodK_ - firstKind(c0 / d, std::abs(s0) * kc / d, complementary2_), s0);
  } else {
    u0_ = firstKind(s0, c0, complementary2_);
  }
  pi0_ = phaseAt(u0_).pi;
  precessionRate_ = momentumMagnitude_ / Ic[2];
  piCoefficient_ = momentumMagnitude_ * (1.0 / Ic[0] - 1.0 / Ic[2]) / rate_;
  principalToCirculation_ = Quat(circulationFromPrincipal_);
  epochFrame_ = epoch_ * principalToCirculation_.conjugate() * alignmentToAxis3(mc).conjugate();
}

double FreeRigidBodyFlow::period() const {
  if (regime_ != Regime::Elliptic || !(complementary2_ > 0.0)) return kInfinity;
  return 4.0 * quarterPeriodK_ / std::abs(rate_);
}

FreeRigidBodyFlow::Phase FreeRigidBodyFlow::phaseAt(double u) const {
  // Reduce u to r in [-K, K] about a multiple j of 2K: sn and cn change sign with every 2K, and
  // Pi(n; am u) = 2 j Pi(n) + Pi(n; am r) (the integrand has period 2K).
  double j = 0.0, r = u;
  if (complementary2_ > 0.0) {
    j = std::nearbyint(u / (2.0 * quarterPeriodK_));
    r = u - 2.0 * j * quarterPeriodK_;
  }
  const double a = std::abs(r);
  double sn = 0.0, cn = 0.0, dn = 0.0, pi = 0.0;
  if (complementary2_ > 0.0 && a > kReflectBeyond * quarterPeriodK_) {
    // Near K, cn -> 0 and am -> pi/2 carry too few digits of u: reflect about K (v = K - |r|),
    // sn(K - v) = cd v, cn(K - v) = kc sd v, dn(K - v) = kc nd v (DLMF 22.4.3), and
    // integral_{|r|}^{K} du / (1 - n sn^2 u) = (k^2 v + (n' - k^2) Pi(n'; am v)) / (n' (1 - n))
    // with n' = (k^2 - n) / (1 - n), from 1 / (1 - n cd^2) = dn^2 / ((1 - n)(1 - n' sn^2)).
    const double v = quarterPeriodK_ - a;
    double cnv = 0.0, dnBoost = 0.0;
    const double snv = boost::math::jacobi_elliptic(k_, v, &cnv, &dnBoost, Elliptic());
    const double kc = std::sqrt(complementary2_);
    const double dnv = std::sqrt(cnv * cnv + complementary2_ * snv * snv);
    sn = std::copysign(cnv / dnv, r);
    cn = kc * snv / dnv;
    dn = kc / dnv;
    if (characteristic_ == 0.0) {
      pi = std::copysign(a, r);  // Pi(0; am r) = r
    } else {
      const double n = characteristic_, k2 = k_ * k_, n2 = (k2 - n) / (1.0 - n);
      const double tail = (k2 * v + (n2 - k2) * thirdKind(n2, snv, cnv, complementary2_)) / (n2 * (1.0 - n));
      pi = std::copysign(completePi_ - tail, r);
    }
  } else {
    double dnBoost = 0.0;
    sn = boost::math::jacobi_elliptic(k_, r, &cn, &dnBoost, Elliptic());
    // Boost's dn loses digits near r = K as k -> 1 (0.4 % at K with kc^2 = 2.5e-5, measured);
    // dn^2 = cn^2 + kc^2 sn^2 is a sum of squares.
    dn = std::sqrt(cn * cn + complementary2_ * sn * sn);
    pi = thirdKind(characteristic_, sn, cn, complementary2_);
  }
  if (j != 0.0) pi += 2.0 * j * completePi_;
  if (std::fmod(j, 2.0) != 0.0) {  // j is a whole number
    sn = -sn;
    cn = -cn;
  }
  return {Vec3(amplitudes_[0] * cn, amplitudes_[1] * sn, amplitudes_[2] * dn), pi};
}

double FreeRigidBodyFlow::rotationAboutMomentum(const Phase& phase, double t) const {
  // dphi/dt = G / I_3 + G (1/I_1 - 1/I_3) / (1 + nu sn^2 u) in the circulation frame (L&L §37's
  // rate with m_3 = a_3 dn u), so phi is linear in t plus an elliptic integral of the third kind
  // of u: integral du / (1 - n sn^2 u) = Pi(n; am u | k).
  return precessionRate_ * t + piCoefficient_ * (phase.pi - pi0_);
}

Vec3 FreeRigidBodyFlow::principalMomentum(double t) const {
  switch (regime_) {
    case Regime::Rest:
      return Vec3::Zero();
    case Regime::Steady:
      return epoch_.conjugate() * angularMomentum_;
    case Regime::Elliptic:
      break;
  }
  return circulationFromPrincipal_.transpose() * phaseAt(u0_ + rate_ * t).momentum;
}

Quat FreeRigidBodyFlow::principalToWorld(double t) const {
  switch (regime_) {
    case Regime::Rest:
      return epoch_;
    case Regime::Steady: {
      const double speed = steadyOmega_.norm();
      return (Quat(Eigen::AngleAxisd(speed * t, steadyOmega_ / speed)) * epoch_).normalized();
    }
    case Regime::Elliptic:
      break;
  }
  // R(t) m(t) = L with R(t) = B Rz(phi(t)) A(m(t)) for a fixed B: so
  // R(t) = R(0) A(m(0))^-1 Rz(phi(t) - phi(0)) A(m(t)), and R(t) m(t) = L holds by construction.
  const Phase phase = phaseAt(u0_ + rate_ * t);
  const double halfTurn = 0.5 * rotationAboutMomentum(phase, t);
  const Quat aboutAxis3(std::cos(halfTurn), 0.0, 0.0, std::sin(halfTurn));
  return epochFrame_ * aboutAxis3 * alignmentToAxis3(phase.momentum / momentumMagnitude_) * principalToCirculation_;
}

}  // namespace rbsim
