// math/rotation: star matrix, axis-angle constructions, the seed's drift correction and the two
// error measures the other suites rely on.
#include "rbsim/math/rotation.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

TEST(Star, IsTheCrossProductMatrix) {
  const Vec3 a(0.3, -1.7, 2.2);
  const Vec3 b(-4.0, 0.5, 1.25);
  EXPECT_TRUE(allNear(star(a) * b, a.cross(b), 1e-15));
  EXPECT_TRUE(allNear(star(a).transpose(), -star(a), 0.0)) << "star(a) must be skew-symmetric";
  EXPECT_TRUE(allNear(star(a) * a, Vec3::Zero(), 1e-15)) << "a x a = 0";
}

TEST(AxisAngle, QuarterTurnAboutZ) {
  const Mat3 R = rotationFromAxisAngle(Vec3(0.0, 0.0, M_PI / 2));
  Mat3 expected;
  expected << 0, -1, 0,
              1, 0, 0,
              0, 0, 1;
  EXPECT_TRUE(allNear(R, expected, 1e-15));
  EXPECT_TRUE(allNear(R * Vec3::UnitX(), Vec3::UnitY(), 1e-15)) << "right-handed: x turns to y";
}

TEST(AxisAngle, ZeroVectorIsIdentity) {
  EXPECT_TRUE(allNear(rotationFromAxisAngle(Vec3::Zero()), Mat3::Identity(), 0.0));
  EXPECT_TRUE(allNear(quatFromAxisAngle(Vec3::Zero()).coeffs(), Quat::Identity().coeffs(), 0.0));
}

TEST(AxisAngle, KeepsTheAxisAndTurnsByItsLength) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    Vec3 axis(u(rng), u(rng), u(rng));
    axis.normalize();
    const double angle = 3.0 * std::abs(u(rng));  // in [0, 3] < pi
    const Mat3 R = rotationFromAxisAngle(angle * axis);
    EXPECT_TRUE(allNear(R * axis, axis, 1e-15)) << "the axis is fixed";
    EXPECT_LT(orthonormalityError(R), 4e-15) << "a few ulps";
    EXPECT_NEAR(R.determinant(), 1.0, 4e-15);
    EXPECT_NEAR(rotationAngleBetween(Mat3::Identity(), R), angle, 1e-14);
    EXPECT_TRUE(allNear(quatFromAxisAngle(angle * axis).toRotationMatrix(), R, 1e-15));
  }
}

// rotationAngleBetween uses atan2(sin, cos), so it must stay accurate near 0 and pi where acos of
// the trace alone would lose half the digits (acos error ~ sqrt(eps) ~ 1e-8 near 0).
TEST(RotationAngleBetween, AccurateNearZeroAndPi) {
  const Mat3 A = rotationFromAxisAngle(Vec3(0.4, -1.1, 0.7));
  const Vec3 axis = Vec3(1.0, 2.0, -0.5).normalized();
  for (double angle : {0.0, 1e-12, 1e-9, 1e-4, 1.0, 3.0, M_PI - 1e-7}) {
    const Mat3 B = A * rotationFromAxisAngle(angle * axis);
    EXPECT_NEAR(rotationAngleBetween(A, B), angle, 1e-14) << "angle " << angle;
    EXPECT_NEAR(rotationAngleBetween(B, A), angle, 1e-14) << "symmetric, angle " << angle;
  }
}

TEST(Orthonormalize, LeavesARotationUnchanged) {
  const Mat3 R = rotationFromAxisAngle(Vec3(-0.3, 2.0, 0.9));
  EXPECT_TRUE(allNear(orthonormalize(R), R, 1e-15));
}

// Columns scaled by positive factors (what a forward Euler step about a body axis produces)
// are restored exactly: Gram-Schmidt only renormalises orthogonal columns.
TEST(Orthonormalize, RemovesPositiveColumnScaling) {
  const Mat3 R = rotationFromAxisAngle(Vec3(1.2, 0.1, -0.4));
  const Mat3 scaled = R * Vec3(2.0, 3.5, 0.25).asDiagonal();
  EXPECT_TRUE(allNear(orthonormalize(scaled), R, 1e-15));
}

TEST(Orthonormalize, RepairsDriftKeepingTheFirstColumnDirection) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Mat3 R = rotationFromAxisAngle(Vec3(0.5, -0.5, 2.0));
  Mat3 noise;
  for (int i = 0; i < 9; ++i) noise(i) = u(rng);
  const Mat3 drifted = R + 1e-3 * noise;
  const Mat3 fixed = orthonormalize(drifted);
  EXPECT_GT(orthonormalityError(drifted), 1e-4) << "the input really is drifted";
  EXPECT_LT(orthonormalityError(fixed), 1e-15);
  EXPECT_NEAR(fixed.determinant(), 1.0, 1e-15);
  EXPECT_TRUE(allNear(fixed.col(0), drifted.col(0).normalized(), 1e-16));
  EXPECT_LT(rotationAngleBetween(R, fixed), 5e-3) << "the repair stays next to the original";
}

TEST(OrthonormalityError, IsFrobeniusNormOfRtRMinusI) {
  // R = s I: R^T R - I = (s^2 - 1) I, whose Frobenius norm is sqrt(3) |s^2 - 1|.
  for (double s : {0.5, 1.0, 1.001, 2.0}) {
    EXPECT_NEAR(orthonormalityError(s * Mat3::Identity()), std::sqrt(3.0) * std::abs(s * s - 1.0), 1e-15);
  }
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = 0.1;  // R^T R - I = [[0, .1, 0], [.1, .01, 0], [0, 0, 0]]
  EXPECT_NEAR(orthonormalityError(shear), std::sqrt(0.01 + 0.01 + 0.0001), 1e-15);
}

// Euler angles, yaw-pitch-roll about z, y', x'' (issue 55): each angle alone is the rotation
// about its axis, the composition is Rz Ry Rx, and angles read back from a rotation give it again,
// at random and at gimbal lock (pitch +-90 degrees, where yaw and roll share an axis).
TEST(EulerZyx, EachAngleTurnsAboutItsAxisInTheStatedOrder) {
  const double yaw = 0.7, pitch = -0.4, roll = 1.9;
  EXPECT_TRUE(allNear(Mat3(quatFromEulerZyx(Vec3(yaw, 0, 0)).toRotationMatrix()), rotationFromAxisAngle(Vec3(0, 0, yaw)), 1e-15));
  EXPECT_TRUE(allNear(Mat3(quatFromEulerZyx(Vec3(0, pitch, 0)).toRotationMatrix()), rotationFromAxisAngle(Vec3(0, pitch, 0)), 1e-15));
  EXPECT_TRUE(allNear(Mat3(quatFromEulerZyx(Vec3(0, 0, roll)).toRotationMatrix()), rotationFromAxisAngle(Vec3(roll, 0, 0)), 1e-15));
  const Mat3 expected = rotationFromAxisAngle(Vec3(0, 0, yaw)) * rotationFromAxisAngle(Vec3(0, pitch, 0)) *
                        rotationFromAxisAngle(Vec3(roll, 0, 0));
  EXPECT_TRUE(allNear(Mat3(quatFromEulerZyx(Vec3(yaw, pitch, roll)).toRotationMatrix()), expected, 1e-14));
}

TEST(EulerZyx, AnglesReadBackFromARotationGiveItAgain) {
  std::mt19937 random(55);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), half(-M_PI / 2, M_PI / 2);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 angles(angle(random), half(random), angle(random));
    const Mat3 R = quatFromEulerZyx(angles).toRotationMatrix();
    const Vec3 back = eulerZyxFromRotation(R);
    EXPECT_TRUE(allNear(back, angles, 1e-9)) << back.transpose() << " from " << angles.transpose();
    EXPECT_LT(rotationAngleBetween(Mat3(quatFromEulerZyx(back).toRotationMatrix()), R), 1e-12);
  }
  for (const double pitch : {M_PI / 2, -M_PI / 2}) {
    const Mat3 R = quatFromEulerZyx(Vec3(0.8, pitch, 0.3)).toRotationMatrix();
    const Vec3 back = eulerZyxFromRotation(R);
    EXPECT_NEAR(back.y(), pitch, 1e-7);
    EXPECT_EQ(back.z(), 0.0) << "at gimbal lock roll is taken as 0";
    EXPECT_LT(rotationAngleBetween(Mat3(quatFromEulerZyx(back).toRotationMatrix()), R), 1e-7);
  }
}

}  // namespace
}  // namespace rbsim
