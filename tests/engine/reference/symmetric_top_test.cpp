// reference/torque_free: the symmetric top (Goldstein §5.6) and free fall. The top's closed form
// is checked against Euler's equations, the kinematics, an RK4 run, and the asymmetric solution
// in the limit I2 -> I1.
#include <cmath>
#include <type_traits>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "reference/euler_rk4.h"
#include "reference/torque_free.h"
#include "test_util.h"

namespace rbsim {
namespace {

using reference::SymmetricTopExact;
using test::allNear;

const Mat3 kTopR0 = rotationFromAxisAngle(Vec3(-0.4, 0.9, 0.2));
const Vec3 kW0(0.6, -0.8, 1.5);

template <typename F>
auto topDerivative(F f, double t, double h = 1e-3) {
  using Value = std::decay_t<decltype(f(t))>;  // evaluated: no Eigen expression outlives f's results
  return Value(((f(t - 2 * h) - f(t + 2 * h)) + 8.0 * (f(t + h) - f(t - h))) / (12.0 * h));
}

struct Top {
  const char* name;
  double I1, I3;
};
constexpr Top kTops[] = {{"oblate", 1.0, 2.0}, {"prolate", 2.0, 0.5}, {"sphere", 1.5, 1.5}};

TEST(SymmetricTopExact, OmegaPrecessesAboutTheSymmetryAxis) {
  for (const Top& top : kTops) {
    SCOPED_TRACE(top.name);
    const SymmetricTopExact exact(top.I1, top.I3, kW0, kTopR0);
    const double Omega = (top.I3 - top.I1) / top.I1 * kW0.z();
    EXPECT_DOUBLE_EQ(exact.bodyPrecessionRate(), Omega);
    const Vec3 I(top.I1, top.I1, top.I3);
    for (double t = -3.0; t <= 10.0; t += 0.41) {
      const Vec3 w = exact.omegaBody(t);
      EXPECT_DOUBLE_EQ(w.z(), kW0.z());
      // The transverse part turns by Omega t about e3 at constant length.
      const double angle = std::atan2(kW0.x() * w.y() - kW0.y() * w.x(), kW0.x() * w.x() + kW0.y() * w.y());
      EXPECT_NEAR(std::remainder(angle - Omega * t, 2.0 * M_PI), 0.0, 1e-13) << "t = " << t;
      EXPECT_NEAR(w.head<2>().norm(), kW0.head<2>().norm(), 1e-14);
      const Vec3 fd = topDerivative([&](double s) { return exact.omegaBody(s); }, t);
      EXPECT_TRUE(allNear(fd, test::eulerRhs(I, w), 1e-9)) << "t = " << t;
    }
  }
}

TEST(SymmetricTopExact, RotationMatchesKinematicsAndRk4) {
  for (const Top& top : kTops) {
    SCOPED_TRACE(top.name);
    const SymmetricTopExact exact(top.I1, top.I3, kW0, kTopR0);
    const Vec3 I(top.I1, top.I1, top.I3);
    const Vec3 L0 = kTopR0 * I.cwiseProduct(kW0);
    EXPECT_NEAR(exact.spacePrecessionRate(), L0.norm() / top.I1, 1e-15);
    EXPECT_TRUE(allNear(exact.rotation(0.0), kTopR0, 1e-15));
    test::Spin s{kW0, kTopR0};
    const double dt = 1e-4;
    for (int step = 1; step <= 30000; ++step) {
      s = test::rk4Spin(I, s, dt);
      if (step % 3000 != 0) continue;
      const double t = step * dt;
      const Mat3 R = exact.rotation(t);
      EXPECT_LT(orthonormalityError(R), 1e-14);
      EXPECT_TRUE(allNear(R * I.cwiseProduct(exact.omegaBody(t)), L0, 1e-13)) << "t = " << t;
      const Mat3 fd = topDerivative([&](double u) { return Mat3(exact.rotation(u)); }, t);
      EXPECT_TRUE(allNear(fd, R * star(exact.omegaBody(t)), 1e-9)) << "t = " << t;
      EXPECT_LT(rotationAngleBetween(R, s.R), 1e-9) << "t = " << t;
    }
  }
}

// With I2 = I1 (1 + eps) the asymmetric solution departs from the top's by O(eps) per radian.
TEST(SymmetricTopExact, IsTheLimitOfTheAsymmetricSolution) {
  const double I1 = 1.0, I3 = 2.0, eps = 1e-9;
  const SymmetricTopExact top(I1, I3, kW0, kTopR0);
  const reference::TorqueFreeExact nearTop(Vec3(I1, I1 * (1.0 + eps), I3), kW0, kTopR0);
  EXPECT_LT(nearTop.modulus(), 1e-4);
  for (double t = 0.0; t <= 5.0; t += 0.5) {
    EXPECT_TRUE(allNear(nearTop.omegaBody(t), top.omegaBody(t), 1e-7)) << "t = " << t;
    EXPECT_LT(rotationAngleBetween(nearTop.rotation(t), top.rotation(t)), 1e-7) << "t = " << t;
  }
}

TEST(SymmetricTopExact, RejectsNonPositiveMoments) {
  EXPECT_THROW(SymmetricTopExact(0.0, 1.0, kW0), std::invalid_argument);
  EXPECT_THROW(SymmetricTopExact(1.0, -1.0, kW0), std::invalid_argument);
}

TEST(Projectile, IsTheFreeFallParabola) {
  const Vec3 x0(1.0, 2.0, -3.0), v0(0.5, 4.0, 0.25), g(0.0, -9.81, 0.0);
  EXPECT_TRUE(allNear(reference::projectile(x0, v0, g, 0.0), x0, 0.0));
  for (double t : {0.25, 1.0, 2.5}) {
    const Vec3 v = topDerivative([&](double s) { return reference::projectile(x0, v0, g, s); }, t);
    EXPECT_TRUE(allNear(v, v0 + g * t, 1e-11));
  }
  EXPECT_TRUE(allNear(reference::projectile(x0, v0, g, 2.0), Vec3(2.0, 10.0 - 19.62, -2.5), 1e-14));
}

}  // namespace
}  // namespace rbsim
