// integrate/free_rigid_body: the closed-form torque-free flow (Boost.Math's Jacobi functions and
// elliptic integral of the third kind) against the independent reference of bench/reference
// (its own AGM Jacobi functions and a quadrature for the rotation about L), against fine RK4 on
// Euler's equations where the reference has no answer (the separatrix), and against the laws it
// must keep: L fixed in the world, the energy, the group property, reversibility.
#include "rbsim/integrate/free_rigid_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "reference/euler_rk4.h"
#include "reference/torque_free.h"

namespace rbsim {
namespace {

double angleBetween(const Quat& a, const Quat& b) { return a.angularDistance(b); }
double angleBetween(const Quat& a, const Mat3& b) { return a.angularDistance(Quat(b)); }

double kineticEnergy(const Vec3& m, const Vec3& I) { return 0.5 * m.cwiseProduct(m).cwiseQuotient(I).sum(); }

// Near the separatrix the motion itself is ill-conditioned: a state rounded to 1e-16 moves
// kc^2 = 1 - k^2 by 1e-16 and so the period by 1e-16 / kc^2 relative (the Dzhanibekov box has
// kc^2 = 1.3e-6). A tolerance for a well-conditioned case, widened by that factor.
double conditioned(double tolerance, const FreeRigidBodyFlow& flow) {
  const double kc2 = 1.0 - flow.modulus() * flow.modulus();
  return std::max(tolerance, 2e-16 / kc2);
}

const Quat kQ0 = Quat(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()));

struct FreeBodyCase {
  std::string name;
  Vec3 I;  // [kg m^2], ascending for the reference
  Vec3 w;  // body-frame omega [rad/s]
};

// Both sides of the separatrix, every sign, near it on both sides (k^2 = 1 - 2.5e-5), and the
// issue's box 1.0 x 0.3 x 0.1 m, 1 kg spun at (0.01, 10, 0) rad/s about its intermediate axis.
std::vector<FreeBodyCase> cases() {
  return {
      {"major_side", Vec3(1.0, 2.0, 3.0), Vec3(1.0, 0.5, 2.0)},
      {"major_side_negative", Vec3(1.0, 2.0, 3.0), Vec3(-0.7, -1.2, -1.5)},
      {"minor_side", Vec3(1.0, 2.0, 3.0), Vec3(2.0, 0.5, 0.3)},
      {"minor_side_negative", Vec3(0.5, 1.5, 1.7), Vec3(-3.0, 1.0, -0.4)},
      {"near_separatrix_minor", Vec3(1.0, 2.0, 3.0), Vec3(0.01, 2.0, 0.0)},
      {"near_separatrix_major", Vec3(1.0, 2.0, 3.0), Vec3(0.0, 2.0, -0.01)},
      {"dzhanibekov_box", Vec3(0.1 / 12.0, 1.01 / 12.0, 1.09 / 12.0), Vec3(0.01, 10.0, 0.0)},
  };
}

// The flow matches the reference's rotation over 20 s to 1e-10 rad: the reference integrates
// the rate of the angle about L by quadrature to 1e-13, this evaluates it in closed form.
TEST(FreeRigidBodyFlow, MatchesTheReferenceSolutionOnEverySide) {
  for (const FreeBodyCase& c : cases()) {
    const reference::TorqueFreeExact exact(c.I, c.w, kQ0.toRotationMatrix());
    const Vec3 L = kQ0 * c.I.cwiseProduct(c.w);
    const FreeRigidBodyFlow flow(kQ0, L, c.I);
    double worst = 0.0, worstMomentum = 0.0;
    for (double t = -3.0; t <= 20.0; t += 0.0731) {
      worst = std::max(worst, angleBetween(flow.principalToWorld(t), exact.rotation(t)));
      const Vec3 m = c.I.cwiseProduct(exact.omegaBody(t));
      worstMomentum = std::max(worstMomentum, (flow.principalMomentum(t) - m).norm() / m.norm());
    }
    EXPECT_LT(worst, 1e-10) << c.name;
    EXPECT_LT(worstMomentum, conditioned(1e-11, flow)) << c.name;
    EXPECT_NEAR(flow.period(), exact.period(), 1e-12 * exact.period()) << c.name;
  }
}

// Random inertias and spins, moments in any order (the flow sorts them): the same check, the
// reference being given the axes sorted.
TEST(FreeRigidBodyFlow, MatchesTheReferenceAtRandomInertiasAndSpins) {
  std::mt19937 random(20261125);
  std::uniform_real_distribution<double> moment(0.05, 5.0), spin(-6.0, 6.0);
  for (int trial = 0; trial < 40; ++trial) {
    Vec3 I(moment(random), moment(random), moment(random));
    const Vec3 w(spin(random), spin(random), spin(random));
    const Quat q0 = Quat::UnitRandom();
    // The reference wants ascending moments: relabel the axes by a rotation P.
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&I](int a, int b) { return I[a] < I[b]; });
    if (I[order[0]] == I[order[1]] || I[order[1]] == I[order[2]]) continue;
    Mat3 P = Mat3::Zero();  // sorted-from-given
    for (int r = 0; r < 3; ++r) P(r, order[r]) = 1.0;
    if (P.determinant() < 0.0) P.row(0) *= -1.0;
    const Vec3 Isorted(I[order[0]], I[order[1]], I[order[2]]);
    const Mat3 R0sorted = q0.toRotationMatrix() * P.transpose();
    const reference::TorqueFreeExact exact(Isorted, P * w, R0sorted);
    const Vec3 L = q0 * I.cwiseProduct(w);
    const FreeRigidBodyFlow flow(q0, L, I);
    double worst = 0.0;
    for (double t = 0.0; t <= 10.0; t += 0.37) {
      const Mat3 reference = exact.rotation(t) * P;  // given-axes-to-world
      worst = std::max(worst, angleBetween(flow.principalToWorld(t), reference));
    }
    EXPECT_LT(worst, 1e-10) << "I = " << I.transpose() << ", w = " << w.transpose();
  }
}

// L stays in the world as it was, the energy is kept, and R(t) m(t) = L to rounding.
TEST(FreeRigidBodyFlow, KeepsMomentumAndEnergyToRounding) {
  for (const FreeBodyCase& c : cases()) {
    const Vec3 L = kQ0 * c.I.cwiseProduct(c.w);
    const FreeRigidBodyFlow flow(kQ0, L, c.I);
    const double energy = kineticEnergy(c.I.cwiseProduct(c.w), c.I);
    for (double t = 0.0; t <= 100.0; t += 1.7) {
      const Quat q = flow.principalToWorld(t);
      const Vec3 m = q.conjugate() * L;  // what the body carries, read through its orientation
      EXPECT_NEAR(kineticEnergy(m, c.I), energy, 1e-12 * energy) << c.name << " t = " << t;
      EXPECT_LT((q * flow.principalMomentum(t) - L).norm(), 1e-13 * L.norm()) << c.name;
    }
  }
}

// Restarting the flow from its own state gives the same motion (the flow is a one-parameter
// group), and running it backwards returns to the start.
TEST(FreeRigidBodyFlow, IsAGroupAndReversible) {
  for (const FreeBodyCase& c : cases()) {
    const Vec3 L = kQ0 * c.I.cwiseProduct(c.w);
    const FreeRigidBodyFlow flow(kQ0, L, c.I);
    const double t1 = 1.234, t2 = 2.345;
    const FreeRigidBodyFlow restarted(flow.principalToWorld(t1), L, c.I);
    EXPECT_LT(angleBetween(restarted.principalToWorld(t2), flow.principalToWorld(t1 + t2)), conditioned(1e-12, flow)) << c.name;
    const FreeRigidBodyFlow back(flow.principalToWorld(t2), L, c.I);
    EXPECT_LT(angleBetween(back.principalToWorld(-t2), kQ0), conditioned(1e-12, flow)) << c.name;
  }
}

// Where the reference has nothing to say: on the separatrix (k = 1, I = (1, 1.5, 3) and
// m = (1, 1, 1) exactly), the flow follows RK4 on Euler's equations at a step of 1e-4 s.
TEST(FreeRigidBodyFlow, FollowsTheSeparatrixAsFineRk4Does) {
  const Vec3 I(1.0, 1.5, 3.0), m0(1.0, 1.0, 1.0);
  const FreeRigidBodyFlow flow(Quat::Identity(), m0, I);
  EXPECT_EQ(flow.modulus(), 1.0);
  EXPECT_TRUE(std::isinf(flow.period()));
  test::Spin spin{m0.cwiseQuotient(I), Mat3::Identity()};
  const double h = 1e-4;
  double worst = 0.0;
  for (int i = 1; i <= 30000; ++i) {
    spin = test::rk4Spin(I, spin, h);
    if (i % 1000 == 0) worst = std::max(worst, angleBetween(flow.principalToWorld(i * h), orthonormalize(spin.R)));
  }
  EXPECT_LT(worst, 1e-9);
}

// The motion depends on I / |L| only: moments from 1e-150 to 1e150 kg m^2 (the scene's range)
// and spins from 1e-10 to 1e8 rad/s give the unit case's orientation after the same turn, where
// squares of |L| (1e-320 to 1e316) would leave the doubles.
TEST(FreeRigidBodyFlow, ScalesOverTheWholeRangeOfMomentsAndSpins) {
  const Vec3 I(1.0, 2.0, 3.0), w(0.3, 1.0, -0.2);
  const FreeRigidBodyFlow unitCase(kQ0, kQ0 * I.cwiseProduct(w), I);
  const Quat expected = unitCase.principalToWorld(1.0);
  for (double scale : {1e-150, 1e-100, 1.0, 1e100, 1e150}) {
    for (double spin : {1e-10, 10.0, 1e8}) {
      const FreeRigidBodyFlow flow(kQ0, kQ0 * Vec3((scale * spin) * I.cwiseProduct(w)), scale * I);
      EXPECT_LT(angleBetween(flow.principalToWorld(1.0 / spin), expected), 1e-13) << "I x " << scale << ", omega x " << spin;
    }
  }
}

// The degenerate regimes are steady or precessing motions with answers in closed form.
TEST(FreeRigidBodyFlow, SteadySpinsSymmetricTopsSpheresAndRest) {
  const double t = 3.7;
  // A spin about each principal axis, the unstable intermediate one included, stays one.
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 I(1.0, 2.0, 3.0);
    const Vec3 w = 1.5 * Vec3::Unit(axis);
    const FreeRigidBodyFlow flow(kQ0, kQ0 * I.cwiseProduct(w), I);
    const Quat expected = Quat(Eigen::AngleAxisd(1.5 * t, kQ0 * Vec3::Unit(axis))) * kQ0;
    EXPECT_LT(angleBetween(flow.principalToWorld(t), expected), 1e-14) << "axis " << axis;
  }
  // A sphere-like inertia turns about its fixed omega.
  {
    const Vec3 I(2.0, 2.0, 2.0), w(0.3, -1.0, 2.0);
    const FreeRigidBodyFlow flow(kQ0, kQ0 * I.cwiseProduct(w), I);
    const Quat expected = Quat(Eigen::AngleAxisd(w.norm() * t, kQ0 * w.normalized())) * kQ0;
    EXPECT_LT(angleBetween(flow.principalToWorld(t), expected), 1e-14);
  }
  // A symmetric top (I1 = I2 and I2 = I3) precesses as the reference's closed form says.
  for (bool oblate : {true, false}) {
    const Vec3 I = oblate ? Vec3(1.0, 1.0, 2.5) : Vec3(0.4, 1.0, 1.0);
    const Vec3 w(0.8, -0.3, 1.7);
    const FreeRigidBodyFlow flow(kQ0, kQ0 * I.cwiseProduct(w), I);
    // The reference's top has its symmetry axis along z: relabel x -> z for the prolate one.
    Mat3 P = Mat3::Identity();
    if (!oblate) P << 0, 1, 0, 0, 0, 1, 1, 0, 0;
    const Vec3 Ip = P * I;
    const reference::SymmetricTopExact top(Ip.x(), Ip.z(), P * w, kQ0.toRotationMatrix() * P.transpose());
    for (double s = 0.0; s < 10.0; s += 0.9) {
      EXPECT_LT(angleBetween(flow.principalToWorld(s), Mat3(top.rotation(s) * P)), 1e-12) << (oblate ? "oblate" : "prolate");
    }
  }
  // At rest nothing moves.
  const FreeRigidBodyFlow rest(kQ0, Vec3::Zero(), Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(rest.principalToWorld(t).coeffs(), kQ0.coeffs());
}

}  // namespace
}  // namespace rbsim
