#pragma once
// An independent numerical reference for the reference suites: classical fixed-step RK4 on
// Euler's torque-free equations in body axes, I1 w1' = (I2 - I3) w2 w3 and cyclic (Goldstein,
// Classical Mechanics §5.5), coupled with the kinematics dR/dt = R [w_body]x.
#include <cmath>

#include "rbsim/math/rotation.h"
#include "rbsim/math/types.h"

namespace rbsim::test {

inline Vec3 eulerRhs(const Vec3& I, const Vec3& w) {
  return Vec3((I.y() - I.z()) / I.x() * w.y() * w.z(), (I.z() - I.x()) / I.y() * w.z() * w.x(),
              (I.x() - I.y()) / I.z() * w.x() * w.y());
}

struct Spin {
  Vec3 w;  // body-frame angular velocity [rad/s]
  Mat3 R;  // body-to-world rotation
};

// The increment of one RK4 step.
inline Vec3 rk4OmegaIncrement(const Vec3& I, const Vec3& w, double h) {
  const Vec3 k1 = eulerRhs(I, w);
  const Vec3 k2 = eulerRhs(I, w + 0.5 * h * k1);
  const Vec3 k3 = eulerRhs(I, w + 0.5 * h * k2);
  const Vec3 k4 = eulerRhs(I, w + h * k3);
  return h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// omega integrated over many steps with compensated (Kahan) summation of the increments: near
// the separatrix the period is so sensitive to the invariants that the rounding of a plain sum
// over 10^6 steps would show in the 8th digit.
class Rk4Omega {
 public:
  Rk4Omega(const Vec3& I, const Vec3& w) : I_(I), w_(w) {}
  void step(double h) {
    const Vec3 y = rk4OmegaIncrement(I_, w_, h) - carry_;
    const Vec3 sum = w_ + y;
    carry_ = (sum - w_) - y;
    w_ = sum;
  }
  const Vec3& omega() const { return w_; }

 private:
  Vec3 I_, w_, carry_ = Vec3::Zero();
};

inline Spin rk4Spin(const Vec3& I, const Spin& s, double h) {
  auto rate = [&I](const Spin& y) { return Spin{eulerRhs(I, y.w), y.R * star(y.w)}; };
  auto add = [](const Spin& y, double a, const Spin& d) { return Spin{y.w + a * d.w, y.R + a * d.R}; };
  const Spin k1 = rate(s);
  const Spin k2 = rate(add(s, 0.5 * h, k1));
  const Spin k3 = rate(add(s, 0.5 * h, k2));
  const Spin k4 = rate(add(s, h, k3));
  return Spin{s.w + h / 6.0 * (k1.w + 2.0 * k2.w + 2.0 * k3.w + k4.w),
              s.R + h / 6.0 * (k1.R + 2.0 * k2.R + 2.0 * k3.R + k4.R)};
}

// omega after time t: whole steps of dt, then one shorter step to land on t exactly.
inline Vec3 rk4OmegaAt(const Vec3& I, const Vec3& w, double t, double dt) {
  Rk4Omega rk(I, w);
  const long n = static_cast<long>(std::floor(t / dt));
  for (long i = 0; i < n; ++i) rk.step(dt);
  rk.step(t - static_cast<double>(n) * dt);
  return rk.omega();
}

// Period of omega measured on RK4 at step dt: the time between the first two downward zero
// crossings of component `axis` (located by linear interpolation within the step). The first
// crossing time goes to *first when given.
inline double rk4Period(const Vec3& I, const Vec3& w, int axis, double dt, double tMax,
                        double* first = nullptr) {
  Rk4Omega rk(I, w);
  double crossings[2];
  int found = 0;
  for (long i = 0; static_cast<double>(i) * dt < tMax && found < 2; ++i) {
    const double before = rk.omega()[axis];
    rk.step(dt);
    const double after = rk.omega()[axis];
    if (before > 0.0 && after <= 0.0) {
      crossings[found++] = (static_cast<double>(i) + before / (before - after)) * dt;
    }
  }
  if (first != nullptr) *first = found > 0 ? crossings[0] : NAN;
  return found == 2 ? crossings[1] - crossings[0] : NAN;
}

}  // namespace rbsim::test
