// integrate/integrator: the integrators beyond seed 004's forward Euler, each against the exact
// solution of its own discrete map where one exists, and against the continuous motion.
//   symplectic-euler  P, L first; then x += dt P_{n+1}/m and q by expmap with omega_{n+1}.
//   implicit-gyro     as symplectic-euler, with L replaced by Catto's implicit gyroscopic step.
//   rk4               classical Runge-Kutta on (x, q, P, L), q normalised at the end.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/integrate/integrator.h"
#include "rbsim/math/rotation.h"
#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using test::boxDef;
using test::worldWith;

// Free fall from x0 with v0 after n steps of dt; t = n dt.
Vec3 fallAfter(Integrator integrator, const Vec3& x0, const Vec3& v0, double dt, int n) {
  World world = worldWith(integrator, dt, Vec3(0.0, -9.81, 0.0));
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 2.5);
  def.position = x0;
  def.velocity = v0;
  world.addBody(def);
  for (int i = 0; i < n; ++i) world.step();
  return world.bodies()[0].position();
}

TEST(SymplecticEuler, FreeFallLeadsTheParabolaByHalfGTDt) {
  const Vec3 x0(0.0, 10.0, 0.0), v0(1.0, 2.0, -0.5), g(0.0, -9.81, 0.0);
  const double dt = 0.01;
  const int n = 1000;
  const double t = n * dt;
  // v_k = v0 + k g dt and x_n = x0 + dt sum_{k=1..n} v_k = x0 + v0 t + g t^2/2 + g t dt/2.
  const Vec3 discrete = x0 + v0 * t + 0.5 * g * t * t + 0.5 * g * t * dt;
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::ImplicitGyro}) {
    // Tolerance: the same sum in floating point, rounding only.
    EXPECT_LE((fallAfter(integrator, x0, v0, dt, n) - discrete).norm(), 1e-12 * discrete.norm())
        << integratorName(integrator);
  }
}

TEST(Rk4, FreeFallIsTheExactParabola) {
  const Vec3 x0(0.0, 10.0, 0.0), v0(1.0, 2.0, -0.5), g(0.0, -9.81, 0.0);
  const double dt = 0.05, t = 200 * dt;
  // A constant force makes x a quadratic in t, which RK4 integrates without truncation error.
  const Vec3 exact = x0 + v0 * t + 0.5 * g * t * t;
  EXPECT_LE((fallAfter(Integrator::Rk4, x0, v0, dt, 200) - exact).norm(), 1e-12 * exact.norm());
}

// Turn after n steps about a body axis, for a box spinning at w rad/s about its z axis.
double turnAfter(Integrator integrator, double w, double dt, int n) {
  World world = worldWith(integrator, dt, Vec3::Zero());
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  const Mat3 R0 = rotationFromAxisAngle(Vec3(0.3, -0.6, 0.2));
  def.orientation = Quat(R0);
  def.angularVelocity = R0.col(2) * w;
  world.addBody(def);
  for (int i = 0; i < n; ++i) world.step();
  return rotationAngleBetween(R0, world.bodies()[0].rotation());
}

TEST(ConstantOmega, SymplecticAndImplicitGyroTurnByExactlyOmegaDtPerStep) {
  // About a principal axis omega x I omega = 0: the gyroscopic step changes nothing, omega stays
  // constant and the expmap rotation is exact. Tolerance: rounding over 100 steps.
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::ImplicitGyro}) {
    EXPECT_NEAR(turnAfter(integrator, 2.0, 0.01, 100), 2.0, 1e-12) << integratorName(integrator);
  }
}

TEST(ConstantOmega, Rk4TurnsByTheAngleOfItsTaylorPolynomial) {
  // For q' = A q with A = [0, omega]/2, RK4 gives q <- T4(dt A) q with T4 the degree-4 Taylor
  // polynomial of exp. On the rotation's complex plane dt A acts as i phi, phi = |omega| dt / 2,
  // so one step turns by 2 atan2(phi - phi^3/6, 1 - phi^2/2 + phi^4/24) = |omega| dt - O(dt^5).
  const double w = 2.0, dt = 0.05;
  const int n = 10;  // a total turn of 1 rad, below pi so the angle is unambiguous
  const double phi = 0.5 * w * dt;
  const double perStep = 2.0 * std::atan2(phi - phi * phi * phi / 6.0, 1.0 - phi * phi / 2.0 + std::pow(phi, 4) / 24.0);
  EXPECT_NEAR(turnAfter(Integrator::Rk4, w, dt, n), n * perStep, 1e-13);
  EXPECT_GT(std::abs(n * perStep - n * w * dt), 1e-10) << "the test distinguishes RK4 from exact";
}

// The spec's asymmetric box, spinning near its intermediate (y) axis at dt = 1/60.
struct Tumble {
  double energy0, energy, momentum0, momentum;
  bool finite = true;
  double largestRise = 0.0;  // largest one-step relative rise of kinetic energy
};

Tumble tumble(Integrator integrator, int steps, double dt = 1.0 / 60.0) {
  World world = worldWith(integrator, dt, Vec3::Zero());
  BodyDef def = boxDef(Vec3(1.0, 0.3, 0.1), 1.0);
  def.angularVelocity = Vec3(0.01, 5.0, 0.01);
  world.addBody(def);
  const RigidBody& body = world.bodies()[0];
  Tumble out{body.kineticEnergy(), 0.0, body.state().angularMomentum.norm(), 0.0};
  for (int i = 0; i < steps; ++i) {
    const double before = body.kineticEnergy();
    world.step();
    out.largestRise = std::max(out.largestRise, body.kineticEnergy() / before - 1.0);
    out.finite = out.finite && body.state().angularMomentum.allFinite() && body.orientation().coeffs().allFinite();
  }
  out.energy = body.kineticEnergy();
  out.momentum = body.state().angularMomentum.norm();
  return out;
}

TEST(TorqueFree, SymplecticEulerAndRk4KeepWorldAngularMomentumToTheBit) {
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::Rk4}) {
    const Tumble t = tumble(integrator, 6000);
    EXPECT_EQ(t.momentum, t.momentum0) << integratorName(integrator);
  }
}

TEST(TorqueFree, ImplicitGyroNeverGainsEnergyAndItsLossIsFirstOrder) {
  // Catto 2015: implicit in the gyroscopic term, the step is dissipative for a free body, so a
  // spin near the unstable intermediate axis cannot blow up: no step may raise the energy
  // (beyond rounding). The price is damping: measured, 100 s at dt = 1/60 keeps 15 % of the
  // energy, at dt = 1/600 keeps 76 % (and |L| 39 % and 87 %). First order: ten times smaller steps, about ten times
  // smaller loss rate (the loss is exponential in time; compare log-rates, within 2x).
  const Tumble coarse = tumble(Integrator::ImplicitGyro, 6000, 1.0 / 60.0);
  const Tumble fine = tumble(Integrator::ImplicitGyro, 60000, 1.0 / 600.0);
  for (const Tumble& t : {coarse, fine}) {
    EXPECT_TRUE(t.finite);
    EXPECT_LE(t.largestRise, 1e-12);
    EXPECT_LT(t.energy, t.energy0);
  }
  const double rateRatio = std::log(coarse.energy / coarse.energy0) / std::log(fine.energy / fine.energy0);
  EXPECT_GT(rateRatio, 5.0);
  EXPECT_LT(rateRatio, 20.0);
}

TEST(TorqueFree, Rk4EnergyErrorIsSmallAtDtOneSixtieth) {
  // Measured over 100 s at dt = 1/60: RK4's energy error is 1.3e-5 relative, while forward Euler
  // (expmap) ends spinning about the minor axis with 10.1 times the energy (|L|^2 / 2 I_min, the
  // most a body with this |L| can have). Bound RK4 with a margin of ~75x the measurement.
  const Tumble rk4 = tumble(Integrator::Rk4, 6000);
  const Tumble expmap = tumble(Integrator::ExpMap, 6000);
  EXPECT_LT(std::abs(rk4.energy / rk4.energy0 - 1.0), 1e-3);
  EXPECT_GT(expmap.energy / expmap.energy0, 5.0);
}

}  // namespace
}  // namespace rbsim
