// reference/torque_free: the exact asymmetric torque-free solution (Landau & Lifshitz, Mechanics
// §37) against the equations it solves, the quantities it conserves, and an independent RK4.
#include "reference/torque_free.h"

#include <cmath>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "reference/euler_rk4.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

struct TorqueFreeCase {
  std::string name;
  Vec3 I;
  Vec3 w0;
};

// Both branches of L&L §37, with positive and negative components, and one case close
// to the separatrix (k^2 = 1 - 2.5e-5).
const std::vector<TorqueFreeCase>& torqueFreeCases() {
  static const std::vector<TorqueFreeCase> all = {
      {"axis3", Vec3(1.0, 2.0, 3.0), Vec3(1.0, 0.5, 2.0)},
      {"axis3_negative", Vec3(1.0, 2.0, 3.0), Vec3(-0.7, -1.2, -1.5)},
      {"axis1", Vec3(1.0, 2.0, 3.0), Vec3(2.0, 0.5, 0.3)},
      {"axis1_negative", Vec3(0.5, 1.5, 1.7), Vec3(-3.0, 1.0, 0.4)},
      {"near_separatrix", Vec3(1.0, 2.0, 3.0), Vec3(0.01, 2.0, 0.0)},
  };
  return all;
}

const Mat3 kTorqueFreeR0 = rotationFromAxisAngle(0.7 * Vec3(1.0, 2.0, 3.0).normalized());

// Fourth-order central difference f'(t) (error h^4 f^(5) / 30).
template <typename F>
auto derivative(F f, double t, double h = 1e-3) {
  using Value = std::decay_t<decltype(f(t))>;  // evaluated: no Eigen expression outlives f's results
  return Value(((f(t - 2 * h) - f(t + 2 * h)) + 8.0 * (f(t + h) - f(t - h))) / (12.0 * h));
}

std::vector<double> sampleTimes() {
  std::vector<double> ts;
  for (int j = -10; j <= 50; ++j) ts.push_back(0.53 * j);
  return ts;
}

TEST(JacobiFunctions, MatchBoostAndCompleteIntegral) {
  for (double k : {0.0, 0.1, 0.5, 0.9, 0.999}) {
    const double kc = std::sqrt((1.0 - k) * (1.0 + k));
    EXPECT_NEAR(reference::completeEllipticK(kc), boost::math::ellint_1(k), 1e-14 * boost::math::ellint_1(k));
    for (double u = -12.0; u <= 12.0; u += 0.37) {
      double cn, dn;
      const double sn = boost::math::jacobi_elliptic(k, u, &cn, &dn);
      const reference::JacobiSnCnDn j = reference::jacobiSnCnDn(u, kc);
      EXPECT_NEAR(j.sn, sn, 1e-13) << "k = " << k << ", u = " << u;
      EXPECT_NEAR(j.cn, cn, 1e-13) << "k = " << k << ", u = " << u;
      EXPECT_NEAR(j.dn, dn, 1e-13) << "k = " << k << ", u = " << u;
    }
  }
}

TEST(TorqueFreeExact, StartsAtTheInitialConditionsOnTheExpectedBranch) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0, kTorqueFreeR0);
    EXPECT_EQ(exact.aboutAxis3(), c.name.rfind("axis3", 0) == 0);
    EXPECT_TRUE(allNear(exact.omegaBody(0.0), c.w0, 1e-14 * c.w0.norm()));
    EXPECT_TRUE(allNear(exact.rotation(0.0), kTorqueFreeR0, 1e-14));
  }
}

TEST(TorqueFreeExact, SatisfiesEulersEquations) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0);
    const double scale = c.w0.squaredNorm();
    for (double t : sampleTimes()) {
      const Vec3 fd = derivative([&](double s) { return exact.omegaBody(s); }, t);
      EXPECT_TRUE(allNear(fd, test::eulerRhs(c.I, exact.omegaBody(t)), 1e-9 * scale)) << "t = " << t;
    }
  }
}

TEST(TorqueFreeExact, ConservesEnergyAndMomentumMagnitude) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0);
    auto energy = [&](const Vec3& w) { return 0.5 * w.dot(c.I.cwiseProduct(w)); };
    const double e0 = energy(c.w0), m0 = c.I.cwiseProduct(c.w0).norm();
    for (double t = -20.0; t <= 100.0; t += 0.731) {
      const Vec3 w = exact.omegaBody(t);
      EXPECT_NEAR(energy(w), e0, 1e-12 * e0) << "t = " << t;
      EXPECT_NEAR(c.I.cwiseProduct(w).norm(), m0, 1e-12 * m0) << "t = " << t;
    }
  }
}

TEST(TorqueFreeExact, RotationIsOrthonormalAndKeepsWorldMomentumFixed) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0, kTorqueFreeR0);
    const Vec3 L0 = kTorqueFreeR0 * c.I.cwiseProduct(c.w0);
    for (double t : sampleTimes()) {
      const Mat3 R = exact.rotation(t);
      EXPECT_LT(orthonormalityError(R), 1e-13) << "t = " << t;
      EXPECT_GT(R.determinant(), 0.0);
      EXPECT_TRUE(allNear(R * c.I.cwiseProduct(exact.omegaBody(t)), L0, 1e-12 * L0.norm())) << "t = " << t;
    }
  }
}

// World L fixed does not pin the angle phi about L; dR/dt = R [w]x does.
TEST(TorqueFreeExact, RotationSatisfiesTheKinematics) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0, kTorqueFreeR0);
    for (double t : sampleTimes()) {
      const Mat3 fd = derivative([&](double s) { return Mat3(exact.rotation(s)); }, t);
      const Mat3 expected = exact.rotation(t) * star(exact.omegaBody(t));
      EXPECT_TRUE(allNear(fd, expected, 1e-9 * c.w0.norm())) << "t = " << t;
    }
  }
}

TEST(TorqueFreeExact, PeriodMatchesFineRk4) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0);
    const double T = exact.period();
    // The sn (axis 2) and cn components change sign every half period; the dn one does not.
    const Vec3 half = exact.omegaBody(0.5 * T);
    const int dn = exact.aboutAxis3() ? 2 : 0;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(half[i], i == dn ? c.w0[i] : -c.w0[i], 1e-12 * c.w0.norm()) << "axis " << i;
    }
    EXPECT_TRUE(allNear(exact.omegaBody(T), c.w0, 1e-12 * c.w0.norm()));
    EXPECT_TRUE(allNear(exact.omegaBody(-3.0 * T), c.w0, 1e-12 * c.w0.norm()));

    const double dt = 1e-5;
    const double measured = test::rk4Period(c.I, c.w0, 1, dt, 2.5 * T);
    EXPECT_NEAR(measured, T, 1e-10 * T);
    EXPECT_TRUE(allNear(test::rk4OmegaAt(c.I, c.w0, T, dt), c.w0, 1e-10 * c.w0.norm()));
  }
}

TEST(TorqueFreeExact, MatchesRk4Orientation) {
  for (const TorqueFreeCase& c : torqueFreeCases()) {
    SCOPED_TRACE(c.name);
    const reference::TorqueFreeExact exact(c.I, c.w0, kTorqueFreeR0);
    const double dt = 1e-4;
    test::Spin s{c.w0, kTorqueFreeR0};
    for (int step = 1; step <= 30000; ++step) {
      s = test::rk4Spin(c.I, s, dt);
      if (step % 5000 != 0) continue;
      const double t = step * dt;
      EXPECT_LT(rotationAngleBetween(exact.rotation(t), s.R), 1e-11) << "t = " << t;
      EXPECT_TRUE(allNear(exact.omegaBody(t), s.w, 1e-11 * c.w0.norm())) << "t = " << t;
    }
  }
}

TEST(TorqueFreeExact, PrincipalAxisSpinsAreSteady) {
  const Vec3 I(1.0, 2.0, 3.0);
  for (int axis : {0, 2}) {
    const Vec3 w0 = -1.5 * Vec3::Unit(axis);
    const reference::TorqueFreeExact exact(I, w0, kTorqueFreeR0);
    EXPECT_EQ(exact.modulus(), 0.0);
    for (double t : {-2.0, 0.3, 1.0, 7.5}) {
      EXPECT_TRUE(allNear(exact.omegaBody(t), w0, 1e-15));
      EXPECT_TRUE(allNear(exact.rotation(t), kTorqueFreeR0 * rotationFromAxisAngle(t * w0), 1e-13)) << "t = " << t;
    }
  }
}

TEST(TorqueFreeExact, RestAndBadInputs) {
  const reference::TorqueFreeExact rest(Vec3(1.0, 2.0, 3.0), Vec3::Zero(), kTorqueFreeR0);
  EXPECT_TRUE(allNear(rest.omegaBody(4.0), Vec3::Zero(), 0.0));
  EXPECT_TRUE(allNear(rest.rotation(4.0), kTorqueFreeR0, 0.0));
  // A pure spin about the intermediate axis lies on the separatrix.
  EXPECT_THROW(reference::TorqueFreeExact(Vec3(1.0, 2.0, 3.0), Vec3(0.0, 3.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(reference::TorqueFreeExact(Vec3(2.0, 1.0, 3.0), Vec3(1.0, 1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(reference::TorqueFreeExact(Vec3(1.0, 1.0, 3.0), Vec3(1.0, 1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(reference::TorqueFreeExact(Vec3(0.0, 1.0, 3.0), Vec3(1.0, 1.0, 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim
