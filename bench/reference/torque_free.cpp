#include "reference/torque_free.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>

namespace rbsim::reference {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Rotation about z by angle a (active, right-handed).
Mat3 rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

// B = Rx(theta) Rz(psi) for the unit body-frame L direction l = (sin t sin p, sin t cos p, cos t):
// B l = e_z (Euler angles as in L&L §35, §37). Its rows are (cos p, -sin p, 0), l x row 1, and l.
Mat3 momentumAlignment(const Vec3& l) {
  const double h = std::hypot(l.x(), l.y());
  const double sp = h > 0.0 ? l.x() / h : 0.0;
  const double cp = h > 0.0 ? l.y() / h : 1.0;
  const Vec3 r1(cp, -sp, 0.0);
  Mat3 b;
  b.row(0) = r1.transpose();
  b.row(1) = l.cross(r1).transpose();
  b.row(2) = l.transpose();
  return b;
}

// Adaptive Gauss-Kronrod quadrature (G15 / K31, with Boost.Math's nodes and weights) of f over
// [a, b] to an absolute error absTol, |K - G| being the error estimate. Boost 1.74's own adaptive
// driver compares a subinterval's error, not scaled by its length, with a scaled tolerance, so
// on short intervals it never meets a tight tolerance and recurses to its maximum depth.
template <class F>
double gaussKronrod(const F& f, double a, double b, double absTol, int depth) {
  using Kronrod = boost::math::quadrature::gauss_kronrod<double, 31>;
  using Gauss = boost::math::quadrature::gauss<double, 15>;
  const auto& x = Kronrod::abscissa();
  const auto& wk = Kronrod::weights();
  const auto& wg = Gauss::weights();
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  const double f0 = f(mid);
  double k = f0 * wk[0], g = f0 * wg[0];
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double pair = f(mid + half * x[i]) + f(mid - half * x[i]);
    k += pair * wk[i];
    if (i % 2 == 0) g += pair * wg[i / 2];  // the Gauss nodes are the even Kronrod ones
  }
  k *= half;
  g *= half;
  if (depth == 0 || std::abs(k - g) <= std::max(absTol, 64.0 * kEps * std::abs(k))) return k;
  return gaussKronrod(f, a, mid, 0.5 * absTol, depth - 1) +
         gaussKronrod(f, mid, b, 0.5 * absTol, depth - 1);
}

}  // namespace

double completeEllipticK(double kc) {
  if (kc <= 0.0) return std::numeric_limits<double>::infinity();
  double a = 1.0, b = kc;
  for (int n = 0; n < 64 && std::abs(a - b) > kEps * a; ++n) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return kPi / (a + b);  // pi / (2 AGM), with AGM = (a + b) / 2 at convergence
}

JacobiSnCnDn jacobiSnCnDn(double u, double kc) {
  if (kc >= 1.0) return {std::sin(u), std::cos(u), 1.0};
  if (kc <= 0.0) return {std::tanh(u), 1.0 / std::cosh(u), 1.0 / std::cosh(u)};  // k = 1
  // sn and cn have period 4K: reduce u to [-2K, 2K] so the phase below stays small.
  const double period = 4.0 * completeEllipticK(kc);
  u -= period * std::nearbyint(u / period);
  // AGM sequence a_n, c_n = (a_{n-1} - b_{n-1}) / 2 from a_0 = 1, b_0 = kc (DLMF §22.20(ii)).
  constexpr int kMax = 32;
  double a[kMax + 1], c[kMax + 1];
  a[0] = 1.0;
  c[0] = 0.0;  // c_0 = k is not used by the recurrence
  double b = kc;
  int n = 0;
  while (n < kMax) {
    ++n;
    a[n] = 0.5 * (a[n - 1] + b);
    c[n] = 0.5 * (a[n - 1] - b);
    b = std::sqrt(a[n - 1] * b);
    if (std::abs(c[n]) <= kEps * a[n]) break;
  }
  // phi_N = 2^N a_N u, phi_{n-1} = (phi_n + asin(c_n / a_n sin phi_n)) / 2 (DLMF §22.20(ii)).
  double phi = std::ldexp(a[n] * u, n);
  for (int i = n; i >= 1; --i) phi = 0.5 * (phi + std::asin(c[i] / a[i] * std::sin(phi)));
  const double sn = std::sin(phi), cn = std::cos(phi);
  // dn = sqrt(1 - k^2 sn^2) = sqrt(cn^2 + kc^2 sn^2): a sum of squares, accurate as k -> 1.
  return {sn, cn, std::sqrt(cn * cn + kc * kc * sn * sn)};
}

TorqueFreeExact::TorqueFreeExact(const Vec3& moments, const Vec3& omega0, const Mat3& R0)
    : I_(moments) {
  const double I1 = I_.x(), I2 = I_.y(), I3 = I_.z();
  if (!(I1 > 0.0 && I1 < I2 && I2 < I3) || !std::isfinite(I3)) {
    throw std::invalid_argument("TorqueFreeExact needs principal moments 0 < I1 < I2 < I3");
  }
  if (!omega0.allFinite()) throw std::invalid_argument("TorqueFreeExact: omega0 not finite");
  if (omega0 == Vec3::Zero()) {
    atRest_ = true;
    period_ = std::numeric_limits<double>::infinity();
    kc_ = 1.0;
    frame_ = R0;
    return;
  }
  const double w1s = omega0.x() * omega0.x(), w2s = omega0.y() * omega0.y(),
               w3s = omega0.z() * omega0.z();
  // 2EI3 - M^2, M^2 - 2EI1 and 2EI2 - M^2 written as sums over the components, so that none
  // cancels catastrophically near the separatrix (E = sum I_i w_i^2 / 2, M^2 = sum I_i^2 w_i^2).
  const double P = I1 * (I3 - I1) * w1s + I2 * (I3 - I2) * w2s;
  const double Q = I2 * (I2 - I1) * w2s + I3 * (I3 - I1) * w3s;
  const double D = I1 * (I2 - I1) * w1s - I3 * (I3 - I2) * w3s;
  if (std::abs(D) <= 8.0 * kEps * (I1 * (I2 - I1) * w1s + I3 * (I3 - I2) * w3s)) {
    throw std::invalid_argument("TorqueFreeExact: on the separatrix M^2 = 2 E I2 (not periodic)");
  }
  aboutAxis3_ = D < 0.0;
  // Amplitudes and frequency: L&L §37, and the same with axes 1 and 3 swapped.
  amplitude_.x() = std::sqrt(P / (I1 * (I3 - I1)));
  amplitude_.z() = std::sqrt(Q / (I3 * (I3 - I1)));
  double k2, kc2;
  if (aboutAxis3_) {
    amplitude_.y() = std::sqrt(P / (I2 * (I3 - I2)));
    wp_ = std::sqrt((I3 - I2) * Q / (I1 * I2 * I3));
    k2 = (I2 - I1) * P / ((I3 - I2) * Q);
    kc2 = (I3 - I1) * -D / ((I3 - I2) * Q);
  } else {
    amplitude_.y() = std::sqrt(Q / (I2 * (I2 - I1)));
    wp_ = std::sqrt((I2 - I1) * P / (I1 * I2 * I3));
    k2 = (I3 - I2) * Q / ((I2 - I1) * P);
    kc2 = (I3 - I1) * D / ((I2 - I1) * P);
  }
  k_ = std::sqrt(std::min(k2, 1.0));
  kc_ = std::sqrt(std::min(kc2, 1.0));
  K_ = completeEllipticK(kc_);
  period_ = 4.0 * K_ / wp_;

  // Phase u0: (sn u0, cn u0) = (S, C) from the sn (axis 2) and cn components; Euler's equations
  // force sign(w1 w2 w3) = sign(A1 A2 A3 sn cn dn), hence the sn component carries the dn sign.
  const int d = aboutAxis3_ ? 2 : 0, c = 2 - d;
  sign_ = omega0[d] >= 0.0 ? 1.0 : -1.0;
  double S = amplitude_.y() > 0.0 ? sign_ * omega0.y() / amplitude_.y() : 0.0;
  double C = amplitude_[c] > 0.0 ? omega0[c] / amplitude_[c] : 1.0;
  const double h = std::hypot(S, C);
  S /= h;
  C /= h;
  // u0 = F(am, k) with am = atan2(S, C); F = sin(am) R_F(cos^2, 1 - k^2 sin^2, 1) for
  // |am| <= pi/2 (DLMF §19.25(i)), and F(am) = +-2K - F(pi -+ am) beyond.
  const double rf = boost::math::ellint_rf(C * C, C * C + kc_ * kc_ * S * S, 1.0);
  u0_ = C >= 0.0 ? S * rf : std::copysign(2.0 * K_, S) - S * rf;

  // Orientation: L&L Euler angles relative to a world-fixed frame with L along its z axis.
  momentum_ = I_.cwiseProduct(omega0).norm();
  frame_ = R0 * momentumAlignment(I_.cwiseProduct(omega0).normalized()).transpose();
  halfPhi_ = phiIntegral(0.5 * period_);
}

Vec3 TorqueFreeExact::omegaBody(double t) const {
  if (atRest_) return Vec3::Zero();
  const JacobiSnCnDn j = jacobiSnCnDn(wp_ * t + u0_, kc_);
  const double wd = sign_ * j.dn, w2 = sign_ * amplitude_.y() * j.sn;
  if (aboutAxis3_) return Vec3(amplitude_.x() * j.cn, w2, amplitude_.z() * wd);
  return Vec3(amplitude_.x() * wd, w2, amplitude_.z() * j.cn);
}

double TorqueFreeExact::phiRate(double t) const {
  // dphi/dt = M (I1 w1^2 + I2 w2^2) / (I1^2 w1^2 + I2^2 w2^2) (L&L §37); for a pure spin
  // about axis 3 (L1 = L2 = 0, theta = 0) the body turns about L at M / I3.
  const Vec3 w = omegaBody(t);
  const double a = I_.x() * w.x() * w.x(), b = I_.y() * w.y() * w.y();
  const double den = I_.x() * a + I_.y() * b;
  if (den == 0.0) return momentum_ / I_.z();
  return momentum_ * (a + b) / den;
}

double TorqueFreeExact::phiIntegral(double t) const {
  if (t == 0.0) return 0.0;
  // Relative tolerance 1e-13 of the integral, which is at least M t / I2 (the rate's minimum).
  const double absTol = 1e-13 * momentum_ / I_.y() * std::abs(t);
  return gaussKronrod([this](double s) { return phiRate(s); }, 0.0, t, absTol, 30);
}

Mat3 TorqueFreeExact::rotation(double t) const {
  if (atRest_) return frame_;
  // phiRate has period period/2 (it depends on w1^2 and w2^2 only).
  const double half = 0.5 * period_;
  const double n = std::floor(t / half);
  const double phi = n * halfPhi_ + phiIntegral(t - n * half);
  const Vec3 l = I_.cwiseProduct(omegaBody(t)).normalized();
  return frame_ * rotZ(phi) * momentumAlignment(l);
}

SymmetricTopExact::SymmetricTopExact(double I1, double I3, const Vec3& omega0, const Mat3& R0)
    : omega0_(omega0), R0_(R0) {
  if (!(I1 > 0.0 && I3 > 0.0 && std::isfinite(I1) && std::isfinite(I3))) {
    throw std::invalid_argument("SymmetricTopExact needs I1 > 0 and I3 > 0");
  }
  Omega_ = (I3 - I1) / I1 * omega0.z();
  const Vec3 L = R0 * Vec3(I1 * omega0.x(), I1 * omega0.y(), I3 * omega0.z());
  spaceRate_ = L.norm() / I1;
  if (L.norm() > 0.0) axisWorld_ = L.normalized();
}

Vec3 SymmetricTopExact::omegaBody(double t) const {
  const double c = std::cos(Omega_ * t), s = std::sin(Omega_ * t);
  return Vec3(c * omega0_.x() - s * omega0_.y(), s * omega0_.x() + c * omega0_.y(), omega0_.z());
}

Mat3 SymmetricTopExact::rotation(double t) const {
  const Mat3 space = Eigen::AngleAxisd(spaceRate_ * t, axisWorld_).toRotationMatrix();
  const Mat3 body = Eigen::AngleAxisd(-Omega_ * t, Vec3::UnitZ()).toRotationMatrix();
  return space * R0_ * body;
}

}  // namespace rbsim::reference
