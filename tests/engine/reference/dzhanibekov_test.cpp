// reference/torque_free: the Dzhanibekov (intermediate-axis) flip of a 1.0 x 0.3 x 0.1 m, 1 kg
// box spun at 5 rad/s about its 0.3 m axis, with a 0.01 rad/s perturbation on the other two.
#include <cmath>
#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

#include "rbsim/mass/mass_properties.h"
#include "reference/euler_rk4.h"
#include "reference/torque_free.h"
#include "test_util.h"

namespace rbsim {
namespace {

// L&L §37 evaluated for this box with mpmath at 30 digits (I = diag(0.1, 1.01, 1.09) / 12 kg m^2,
// case M^2 < 2 E I2, k^2 = 1 - 2.0466e-7, wp = 4.0862366 rad/s): T = 4 K(k) / wp.
constexpr double kOmegaPeriodMpmath = 8.895484030056223805;  // [s]

std::string fixed(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

TEST(Dzhanibekov, BoxFlipPeriod) {
  const Vec3 I = cuboidInertia(1.0, Vec3(1.0, 0.3, 0.1)).diagonal();
  // I = m/12 (b^2 + c^2, a^2 + c^2, a^2 + b^2): the 0.3 m axis (y) is the intermediate one.
  ASSERT_LT(I.x(), I.y());
  ASSERT_LT(I.y(), I.z());
  const Vec3 w0(0.01, 5.0, 0.01);
  const reference::TorqueFreeExact exact(I, w0);
  EXPECT_FALSE(exact.aboutAxis3());  // M^2 < 2 E I2 by 2.6e-9 J kg m^2: it tumbles about x

  // omega_y reverses every half period: the box flips over every T / 2.
  const double T = exact.period();
  const double flip = 0.5 * T;
  RecordProperty("omega_period_s", fixed(T));
  RecordProperty("flip_interval_s", fixed(flip));
  std::printf("[ box ] omega period T = %.12f s, flip every T/2 = %.12f s, k = %.12f\n", T, flip,
              exact.modulus());
  EXPECT_NEAR(T, kOmegaPeriodMpmath, 1e-11 * T);

  // Independent: RK4 at dt = 1e-5 on Euler's equations, between two downward zero crossings of
  // omega_y; the first is the middle of the first flip.
  double firstFlip = 0.0;
  const double measured = test::rk4Period(I, w0, 1, 1e-5, 1.5 * T, &firstFlip);
  std::printf("[ box ] RK4 (dt = 1e-5) period = %.12f s, first flip centred at t = %.6f s\n",
              measured, firstFlip);
  RecordProperty("rk4_period_s", fixed(measured));
  RecordProperty("first_flip_s", fixed(firstFlip));
  EXPECT_NEAR(measured, T, 1e-10 * T);

  // Half a period on, omega_y and omega_z have reversed and omega_x (the dn component) has not.
  EXPECT_TRUE(test::allNear(exact.omegaBody(flip), Vec3(0.01, -5.0, -0.01), 1e-10));
  // Mid-flip the spin lies in the x-z plane: w = (A1, 0, -A3) with, to O(1e-4),
  // A1 = 5 sqrt(I2 (I3 - I2) / (I1 (I3 - I1))) and A3 = 5 sqrt(I2 (I2 - I1) / (I3 (I3 - I1))).
  const Vec3 mid = exact.omegaBody(firstFlip);
  EXPECT_NEAR(mid.y(), 0.0, 1e-7);
  EXPECT_NEAR(mid.x(), 5.0 * std::sqrt(I.y() * (I.z() - I.y()) / (I.x() * (I.z() - I.x()))), 1e-3);
  EXPECT_NEAR(mid.z(), -5.0 * std::sqrt(I.y() * (I.y() - I.x()) / (I.z() * (I.z() - I.x()))), 1e-3);
}

}  // namespace
}  // namespace rbsim
