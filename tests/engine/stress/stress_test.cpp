// Stress: numerical stability of every integrator under violent torque-free spins, and the
// SimulationError World::step throws instead of letting a state become NaN.
//
// The spinner: principal moments I = (0.001, 0.1, 1) kg m^2 (ratio 1:100:1000), spun at |omega|
// = 100 or 1000 rad/s about the body direction (1, 1, 1), zero gravity, no sleeping, 1e6 steps
// (RBSIM_STRESS=long; 1e5 by default) at dt = 1/60 s (16 667 s). |omega| dt is 1.7 and 16.7 rad per step, but the rate that matters is
// the nutation frequency Omega ~ omega sqrt((I3 - I1)(I3 - I2) / (I1 I2)) ~ 5500 rad/s at
// 100 rad/s (L&L section 37): Omega dt ~ 90 rad, so no integrator resolves the motion and each
// shows its long-run character. (I1 + I2 < I3: no mass distribution has this tensor; the
// integrators only see an SPD matrix, and the extreme ratio only makes the test harsher.)
//
// With world L fixed and q unit, E = sum Pi_i^2 / (2 I_i) lies in the envelope
// [|L|^2 / (2 I_max), |L|^2 / (2 I_min)] = [0.917, 917.35] E0: spinning about the major axis at
// one end, about the minor axis at the other. Measured (Release, 1e6 steps, E per step):
//
//   integrator         |omega|  E_end/E0  max E/E0  min E/E0  |L_end|/|L0|  throws
//   euler-matrix        100     371.34    552.05    1         exact         no
//   euler-quat          100     917.35    917.35    1         exact         no
//   expmap              100      86.69     86.69    1         exact         no
//   symplectic-euler    100      86.69     86.69    1         exact         no
//   rk4                 100     917.35    917.35    1         exact         no
//   implicit-gyro       100       1.169     1.169   1         1.129         no
//   dlm                 100       6.47    917.35    0.918     exact         no
//   euler-matrix       1000     276.09    370.24    1         exact         no
//   euler-quat         1000     917.35    917.35    1         exact         no
//   expmap             1000     913.65    913.65    1         exact         no
//   symplectic-euler   1000     913.65    913.65    1         exact         no
//   rk4                1000     917.35    917.35    1         exact         no
//   implicit-gyro      1000     5.8e-5      1       5.8e-5    0.008         no
//   dlm                1000     753.42    917.35    0.918     exact         no
//
// So nothing diverges at these spins: every state stays finite, |q| - 1 and ||R^T R - I|| stay
// below 3e-15. All but implicit-gyro keep world L to the bit (no torque: L + dt * 0 == L) and
// therefore stay in the envelope, which they cross from end to end; dlm keeps a small energy band
// only once Omega dt < 1 (DlmBandIsSecondOrderOnceTheNutationIsResolved). implicit-gyro damps;
// with Catto's single Newton iteration it GAINED 17 % in its first step at 100 rad/s, so the
// step now iterates to convergence (ImplicitGyroNeverGainsEnergyAtLargeOmegaDt). rk4 leaves the finite
// numbers only at absurd spins (1e78 to 1e80 rad/s, where (|omega| dt)^4 overflows).
#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "stress/stress_length.h"
#include "test_util.h"
#include "../../sanitized_build.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

constexpr double kSpinDt = 1.0 / 60.0;       // [s]
// 1e6 steps (16 667 s) in the long stress run, 1e5 by default (stress_length.h).
const long kSpinSteps = test::stressSteps(100000, 1000000);
constexpr long kCheckEvery = 10000;          // steps between full checks of the state
constexpr double kInertiaScale = 1e-3;       // [kg m^2]: I = kInertiaScale * diag(1, 100, 1000)
constexpr double kRotationUnitTolerance = 1e-12;  // | |q| - 1 | and ||R^T R - I||_F
constexpr double kRoundingFactor = 1e-12;    // relative slack on bounds that hold exactly
// With Catto's single Newton iteration the run reached 1.1692 E0; iterated to convergence the
// step cannot gain energy (integrator.cpp), so the ceiling is E0 itself.
constexpr double kImplicitGyroCeilingAt100 = 1.0 + 1e-12;
// Measured E_end / E0 = 0.091 with the converged step (5.8e-5 with one iteration): at 1000
// rad/s the implicit step removes most of the energy.
constexpr double kImplicitGyroDampingAt1000 = 0.2;
// Newmark's midpoint keeps E and |L| to its Newton tolerance (1e-14 of |w| a step), which a run
// of 1e5 steps adds up: relative bound [1].
constexpr double kNewmarkConservation = 1e-8;

BodyDef spinnerDef(double rate) {
  BodyDef def;
  def.name = "spinner";
  def.mesh = std::make_shared<const Mesh>(makeBox(Vec3(1.0, 0.3, 0.1)));
  def.mass = 1.0;
  def.inertiaBody = kInertiaScale * Vec3(1.0, 100.0, 1000.0).asDiagonal().toDenseMatrix();
  const Mat3 R0 = rotationFromAxisAngle(Vec3(0.3, -0.6, 0.2));
  def.orientation = Quat(R0);
  def.angularVelocity = R0 * (rate * Vec3(1.0, 1.0, 1.0).normalized());  // no principal axis
  return def;
}

World spinWorld(Integrator integrator, double dt) {
  Settings s;
  s.integrator = integrator;
  s.timeStep = dt;
  s.gravity = Vec3::Zero();
  s.allowSleep = false;
  return World(s);
}

bool everythingFinite(const RigidBody& b) {
  return b.position().allFinite() && b.orientation().coeffs().allFinite() &&
         b.state().linearMomentum.allFinite() && b.state().angularMomentum.allFinite() &&
         b.rotation().allFinite() && b.velocity().allFinite() && b.angularVelocity().allFinite() &&
         std::isfinite(b.kineticEnergy());
}

struct SpinRun {
  double energy0 = 0.0, energyLow = 0.0, energyHigh = 0.0;  // E0 and the envelope for |L0| [J]
  double energyMin = 0.0, energyMax = 0.0, energyEnd = 0.0;  // over every step [J]
  double momentumRatioEnd = 0.0;                              // |L_end| / |L0|
  bool momentumExact = true;   // world L bit-identical to L0 after every step
  bool finite = true;          // at every check
  double worstUnitError = 0.0;  // max over checks of | |q| - 1 | and ||R^T R - I||_F
};

SpinRun spin(Integrator integrator, double rate, double dt, long steps) {
  World world = spinWorld(integrator, dt);
  world.addBody(spinnerDef(rate));
  const RigidBody& body = world.bodies()[0];
  const Vec3 L0 = body.state().angularMomentum;
  SpinRun run;
  run.energy0 = run.energyMin = run.energyMax = body.kineticEnergy();
  run.energyLow = L0.squaredNorm() / (2.0 * body.principalMoments().maxCoeff());
  run.energyHigh = L0.squaredNorm() / (2.0 * body.principalMoments().minCoeff());
  for (long i = 1; i <= steps; ++i) {
    world.step();
    const double energy = body.kineticEnergy();
    run.energyMin = std::min(run.energyMin, energy);
    run.energyMax = std::max(run.energyMax, energy);
    run.momentumExact = run.momentumExact && body.state().angularMomentum == L0;
    if (i % kCheckEvery == 0 || i == steps) {
      run.finite = run.finite && everythingFinite(body);
      run.worstUnitError = std::max({run.worstUnitError, std::abs(body.orientation().norm() - 1.0),
                                     orthonormalityError(body.rotation())});
    }
  }
  run.energyEnd = body.kineticEnergy();
  run.momentumRatioEnd = body.state().angularMomentum.norm() / L0.norm();
  return run;
}

class StressSpin : public testing::TestWithParam<Integrator> {
 protected:
  void check(double rate) {
    const Integrator integrator = GetParam();
    const SpinRun run = spin(integrator, rate, kSpinDt, kSpinSteps);  // must not throw
    EXPECT_TRUE(run.finite);
    EXPECT_LE(run.worstUnitError, kRotationUnitTolerance);
    RecordProperty("energy_end_over_e0", std::to_string(run.energyEnd / run.energy0));
    RecordProperty("energy_max_over_e0", std::to_string(run.energyMax / run.energy0));
    if (integrator == Integrator::ImplicitGyro) {
      // Catto's step is dissipative when its implicit equation is solved; one Newton iteration
      // at Omega dt ~ 90 rad is not that solution (see the DISABLED_ test below).
      const double ceiling = rate < 500.0 ? kImplicitGyroCeilingAt100 : 1.0 + kRoundingFactor;
      EXPECT_LE(run.energyMax, ceiling * run.energy0);
      if (rate > 500.0) {
        EXPECT_LE(run.energyEnd, kImplicitGyroDampingAt1000 * run.energy0);
      }
      return;
    }
    if (integrator == Integrator::Newmark) {
      // The midpoint keeps the energy and |I w| = |L| (integrator.cpp), to the Newton tolerance,
      // at any |omega| dt; L's direction in the world is not kept exactly.
      EXPECT_NEAR(run.energyMin / run.energy0, 1.0, kNewmarkConservation);
      EXPECT_NEAR(run.energyMax / run.energy0, 1.0, kNewmarkConservation);
      EXPECT_NEAR(run.momentumRatioEnd, 1.0, kNewmarkConservation);
      return;
    }
    // No torque: every other integrator adds dt * 0 to L, so L stays bit-identical, q stays unit,
    // and the energy cannot leave the envelope of the fixed |L|.
    EXPECT_TRUE(run.momentumExact);
    EXPECT_GE(run.energyMin, run.energyLow * (1.0 - kRoundingFactor));
    EXPECT_LE(run.energyMax, run.energyHigh * (1.0 + kRoundingFactor));
  }
};

TEST_P(StressSpin, At100RadPerSecondStaysFiniteUnitAndInItsEnergyBound) { check(100.0); }
TEST_P(StressSpin, At1000RadPerSecondStaysFiniteUnitAndInItsEnergyBound) { check(1000.0); }

INSTANTIATE_TEST_SUITE_P(AllIntegrators, StressSpin, testing::ValuesIn(test::allIntegrators()),
                         test::integratorParamName);

TEST(StressSpinDlm, DlmBandIsSecondOrderOnceTheNutationIsResolved) {
  // Omega ~ 5500 rad/s at 100 rad/s: dt = 1e-4 s gives Omega dt ~ 0.55, dt = 1e-5 s ~ 0.055.
  // DLM is a second-order symplectic splitting, so its energy error is a bounded band ~ dt^2.
  // Measured over 1e5 steps: max |E/E0 - 1| = 6.6e-3 and 6.2e-5 (ratio 108).
  constexpr long kSteps = 100000;
  const SpinRun coarse = spin(Integrator::Dlm, 100.0, 1e-4, kSteps);
  const SpinRun fine = spin(Integrator::Dlm, 100.0, 1e-5, kSteps);
  const auto band = [](const SpinRun& r) {
    return std::max(r.energyMax / r.energy0 - 1.0, 1.0 - r.energyMin / r.energy0);
  };
  EXPECT_TRUE(coarse.momentumExact && fine.momentumExact);
  EXPECT_LE(band(coarse), 2e-2);
  EXPECT_LE(band(fine), 2e-4);
  EXPECT_GT(band(coarse) / band(fine), 50.0);   // 100 for exactly second order
  EXPECT_LT(band(coarse) / band(fine), 200.0);
}

// The exact root w2 of I (w2 - w1) + dt w2 x I w2 = 0 has w2.I w2 = w2.I w1, so E2 <= E1 by
// Cauchy-Schwarz; Catto's single Newton iteration did not (one step of this spinner at 100 rad/s,
// dt = 1/60 s raised E by 16.4 %). The step now iterates to convergence.
TEST(StressSpin, ImplicitGyroNeverGainsEnergyAtLargeOmegaDt) {
  const SpinRun run = spin(Integrator::ImplicitGyro, 100.0, kSpinDt, 1);
  EXPECT_LE(run.energyEnd, run.energy0 * (1.0 + kRoundingFactor));
}

// At |omega| = 1e80 rad/s RK4's stage increments grow like (|omega| dt)^4 ~ 1e313 and overflow;
// every other integrator turns q by a normalised map and stays finite (measured at dt = 1/60 s:
// rk4 is finite at 1e78 rad/s and throws at 1e80; expmap, symplectic-euler and implicit-gyro
// throw only between 1e150 and 1e160 rad/s, where |omega|^2 inside a norm overflows).
constexpr double kOverflowSpin = 1e80;  // [rad/s]

TEST(StressDivergence, Rk4AtAnExtremeSpinThrowsSimulationErrorNamingBodyIntegratorAndDt) {
  World world = spinWorld(Integrator::Rk4, kSpinDt);
  world.addBody(spinnerDef(1.0));
  PoseEvent kick;  // sets the extreme spin at step 5 (t = 5 dt >= 4.5 dt > 4 dt)
  kick.body = world.idAt(0);
  kick.time = 4.5 * kSpinDt;
  kick.angularVelocity = kOverflowSpin * Vec3(1.0, -2.0, 0.5).normalized();
  world.addPoseEvent(kick);
  const RigidBody& body = world.bodies()[0];
  for (int i = 0; i < 5; ++i) {
    world.step();
    ASSERT_TRUE(everythingFinite(body)) << "step " << i;
  }
  const Vec3 spinBefore = body.angularVelocity();
  const std::uint64_t hashBefore = world.stateHash();
  std::string message;
  try {
    world.step();
    FAIL() << "rk4 at 1e80 rad/s should leave the finite numbers";
  } catch (const SimulationError& e) {
    message = e.what();
  }
  std::ostringstream dt;
  dt << "dt = " << kSpinDt << " s";
  EXPECT_NE(message.find("'spinner'"), std::string::npos) << message;
  EXPECT_NE(message.find("rk4"), std::string::npos) << message;
  EXPECT_NE(message.find(dt.str()), std::string::npos) << message;
  EXPECT_NE(message.find("step 5"), std::string::npos) << message;
  EXPECT_NE(message.find("orientation"), std::string::npos) << message;  // the quantity that overflowed
  // The failed step is undone (issue 56, item 6): the body holds its state before the step, and the
  // pose event that set the extreme spin waits to be applied again.
  EXPECT_EQ(world.stepCount(), 5u);
  EXPECT_EQ(world.stateHash(), hashBefore);
  EXPECT_EQ(body.angularVelocity(), spinBefore);
  EXPECT_TRUE(body.state().angularMomentum.allFinite() && body.orientation().coeffs().allFinite());
  EXPECT_THROW(world.step(), SimulationError) << "a retry fails the same way, never with NaN";
  EXPECT_EQ(world.stateHash(), hashBefore);
}

TEST(StressDivergence, AtTheSameSpinEveryOtherIntegratorStaysFinite) {
  for (Integrator integrator : test::allIntegrators()) {
    if (integrator == Integrator::Rk4) continue;
    World world = spinWorld(integrator, kSpinDt);
    BodyDef def = spinnerDef(1.0);
    def.angularVelocity = kOverflowSpin * Vec3(1.0, -2.0, 0.5).normalized();
    world.addBody(def);
    const RigidBody& body = world.bodies()[0];
    const Vec3 L0 = body.state().angularMomentum;
    // 25 steps under the sanitizers, where Newmark's stalled rotation solve makes each step slow
    // (the normal build runs 100).
    for (int i = 0; i < (test::kSanitizedBuild ? 25 : 100); ++i) {
      ASSERT_NO_THROW(world.step()) << integratorName(integrator) << " step " << i;
      ASSERT_TRUE(everythingFinite(body)) << integratorName(integrator) << " step " << i;
    }
    EXPECT_LE(std::abs(body.orientation().norm() - 1.0), kRotationUnitTolerance) << integratorName(integrator);
    if (integrator == Integrator::Newmark) {
      EXPECT_NEAR(body.state().angularMomentum.norm() / L0.norm(), 1.0, kNewmarkConservation);
    } else if (integrator != Integrator::ImplicitGyro) {
      EXPECT_TRUE(body.state().angularMomentum == L0);
    }
  }
}

}  // namespace
}  // namespace rbsim
