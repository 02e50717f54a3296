// Stress: tiny and huge masses (1e-6 and 1e6 kg, inertia in proportion) at time steps across the
// accepted range [kMinTimeStep, kMaxTimeStep] = [1e-6, 0.1] s, and a clear error outside it.
// Each case is either the physically right answer, to a stated tolerance, or an exception naming
// the cause; never NaN. 1000 steps per case, so t runs from 1 ms (dt = 1e-6 s) to 100 s.
//
// Measured (relative errors after 1000 steps, worst over both masses):
//   free fall vs the integrator's own discrete parabola    <= 4.5e-14 (every integrator, dt)
//   constant torque, L - tau t (all but implicit-gyro)     <= 3.6e-14
//   implicit-gyro, L - tau t at dt = 1e-6/1e-4/1e-2/0.1    2.7e-13 / 2.4e-5 / 0.42 / 0.54, and
//                                                          |L| never above |tau| t
//   1e-6 or 1e6 kg vs 1 kg, same spin: rotation apart      <= 2.2e-11 rad, E/E0 apart <= 2.4e-13
//   generic spin, |E/E0 - 1|: rk4 4e-15/1e-15/2.1e-6/4.5e-2, dlm 2.5e-14/4.2e-10/4.1e-6/5.7e-3
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"
#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using test::boxDef;

constexpr double kTinyMass = 1e-6;  // [kg]
constexpr double kHugeMass = 1e6;   // [kg]
constexpr double kTimeSteps[] = {1e-6, 1e-4, 1e-2, 0.1};  // [s], kMinTimeStep to kMaxTimeStep
constexpr int kSteps = 1000;
const Vec3 kExtents(1.0, 0.3, 0.1);         // [m], the spec's asymmetric box
const Vec3 kGravity(0.0, -9.81, 0.0);       // [m/s^2]
const Vec3 kLaunch(1.0, 2.0, -0.5);         // v0 [m/s]
const Vec3 kSpin(3.0, 4.0, 5.0);            // omega0, body frame [rad/s]
const Vec3 kTorquePerKg(0.3, -0.2, 0.5);    // tau / m [N m/kg]: the same spin-up at any mass
constexpr double kRounding = 1e-12;         // relative; measured errors are <= 5e-14

const Mat3& initialRotation() {
  static const Mat3 R0 = rotationFromAxisAngle(Vec3(0.3, -0.6, 0.2));
  return R0;
}

World worldAt(Integrator integrator, double dt, const Vec3& gravity) {
  Settings s;
  s.integrator = integrator;
  s.timeStep = dt;
  s.gravity = gravity;
  s.allowSleep = false;
  return World(s);
}

BodyDef bodyOf(double mass) {
  BodyDef def = boxDef(kExtents, mass);  // cuboidInertia: I proportional to m
  def.orientation = Quat(initialRotation());
  return def;
}

bool finiteAndUnit(const RigidBody& b) {
  return b.state().position.allFinite() && b.orientation().coeffs().allFinite() &&
         b.state().linearMomentum.allFinite() && b.state().angularMomentum.allFinite() &&
         std::isfinite(b.kineticEnergy()) && std::abs(b.orientation().norm() - 1.0) <= kRounding &&
         orthonormalityError(b.rotation()) <= kRounding;
}

// Each integrator's position after n steps of constant g is x0 + v0 t + g t^2/2 + c g t dt/2:
// forward Euler (x += dt v_n) lags by g t dt/2 (c = -1); symplectic Euler and implicit-gyro
// (x += dt v_{n+1}) lead by it (c = +1); rk4, dlm, newmark, exact and exact4 (a constant force's
// half kicks around an exact drift) are exact for it (c = 0).
double parabolaOffset(Integrator integrator) {
  switch (integrator) {
    case Integrator::EulerMatrix:
    case Integrator::EulerQuat:
    case Integrator::ExpMap: return -1.0;
    case Integrator::SymplecticEuler:
    case Integrator::ImplicitGyro: return 1.0;
    case Integrator::Rk4:
    case Integrator::Dlm:
    case Integrator::Newmark:
    case Integrator::Exact:
    case Integrator::Exact4: return 0.0;
  }
  return 0.0;
}

class StressMassAndStep : public testing::TestWithParam<Integrator> {};

TEST_P(StressMassAndStep, FreeFallIsTheIntegratorsKnownParabola) {
  const Integrator integrator = GetParam();
  for (double mass : {kTinyMass, kHugeMass}) {
    for (double dt : kTimeSteps) {
      World world = worldAt(integrator, dt, kGravity);
      BodyDef def = bodyOf(mass);
      def.velocity = kLaunch;
      def.angularVelocity = initialRotation() * Vec3(0.2, -0.1, 0.3);  // a slow tumble alongside
      world.addBody(def);
      for (int i = 0; i < kSteps; ++i) world.step();
      const RigidBody& body = world.bodies()[0];
      const double t = kSteps * dt;
      const Vec3 offset = parabolaOffset(integrator) * 0.5 * kGravity * t * dt;
      const Vec3 expected = kLaunch * t + 0.5 * kGravity * t * t + offset;
      const double scale = kLaunch.norm() * t + 0.5 * kGravity.norm() * t * t;  // [m]
      EXPECT_TRUE(finiteAndUnit(body)) << "m " << mass << " dt " << dt;
      EXPECT_TRUE(test::allNear(body.position(), expected, kRounding * scale)) << "m " << mass << " dt " << dt;
      // Every integrator adds dt F/m to v each step: v = v0 + g t up to rounding.
      EXPECT_TRUE(test::allNear(body.velocity(), Vec3(kLaunch + kGravity * t), kRounding * (kLaunch.norm() + kGravity.norm() * t)))
          << "m " << mass << " dt " << dt;
      // The test can tell the three formulas apart: g t dt/2 is >= 2e-6 of the displacement.
      ASSERT_GT(0.5 * kGravity.norm() * t * dt, 1e3 * kRounding * scale);
    }
  }
}

TEST_P(StressMassAndStep, ConstantTorqueGivesLEqualsTauT) {
  // Euler's second law: dL/dt = tau in the world frame, so from rest L(t) = tau t, whatever the
  // body does. Every integrator but implicit-gyro adds dt tau to L (dlm in two halves).
  const Integrator integrator = GetParam();
  for (double mass : {kTinyMass, kHugeMass}) {
    for (double dt : kTimeSteps) {
      World world = worldAt(integrator, dt, Vec3::Zero());
      world.addBody(bodyOf(mass));
      RigidBody& body = world.body(world.idAt(0));
      const Vec3 tau = mass * kTorquePerKg;
      double largestRatio = 0.0;  // max over steps of |L| / |tau t|
      for (int i = 1; i <= kSteps; ++i) {
        body.applyTorque(tau);
        world.step();
        largestRatio = std::max(largestRatio, body.state().angularMomentum.norm() / (tau.norm() * i * dt));
      }
      const Vec3 impulse = tau * (kSteps * dt);
      const double error = (body.state().angularMomentum - impulse).norm() / impulse.norm();
      EXPECT_TRUE(finiteAndUnit(body)) << "m " << mass << " dt " << dt;
      if (integrator == Integrator::Newmark) {
        // The midpoint holds R_n^T tau in the body over the step and gives L = R I w: Euler's
        // law holds only as dt -> 0, at second order (7.7e-9 at dt = 1e-6 s, 7.7e-5 at 1e-4 s).
        if (dt <= 1e-6) {
          EXPECT_LE(error, 1e-8) << "m " << mass << " dt " << dt;
        }
        continue;
      }
      if (integrator != Integrator::ImplicitGyro) {
        EXPECT_LE(error, kRounding) << "m " << mass << " dt " << dt;
        continue;
      }
      // implicit-gyro replaces L by R I w2 with w2 its damped gyroscopic solution: Euler's law
      // holds only as dt -> 0 (error 2.7e-13 at dt = 1e-6 s), and the damping never adds to |L|.
      EXPECT_LE(largestRatio, 1.0 + kRounding) << "m " << mass << " dt " << dt;
      if (dt <= 1e-6) {
        EXPECT_LE(error, 1e-11) << "m " << mass;
      }
      if (dt >= 1e-2) {
        EXPECT_GT(error, 0.1) << "m " << mass << " dt " << dt << ": the measured deviation";
      }
    }
  }
}

TEST_P(StressMassAndStep, TinyAndHugeMassesSpinExactlyAsOneKilogram) {
  // With I proportional to m, omega = I^-1 L does not depend on m: the torque-free motion is the
  // same for every mass, and only rounding may tell them apart.
  const Integrator integrator = GetParam();
  for (double dt : kTimeSteps) {
    Mat3 rotation[3];
    double energyRatio[3];
    const double masses[3] = {1.0, kTinyMass, kHugeMass};
    for (int k = 0; k < 3; ++k) {
      World world = worldAt(integrator, dt, Vec3::Zero());
      BodyDef def = bodyOf(masses[k]);
      def.angularVelocity = initialRotation() * kSpin;
      world.addBody(def);
      const RigidBody& body = world.bodies()[0];
      const Vec3 L0 = body.state().angularMomentum;
      const double energy0 = body.kineticEnergy();
      double largestEnergy = energy0, worstEnergyError = 0.0;
      for (int i = 0; i < kSteps; ++i) {
        world.step();
        largestEnergy = std::max(largestEnergy, body.kineticEnergy());
        worstEnergyError = std::max(worstEnergyError, std::abs(body.kineticEnergy() / energy0 - 1.0));
      }
      rotation[k] = body.rotation();
      energyRatio[k] = body.kineticEnergy() / energy0;
      EXPECT_TRUE(finiteAndUnit(body)) << "m " << masses[k] << " dt " << dt;
      if (integrator == Integrator::ImplicitGyro) {
        EXPECT_LE(largestEnergy, energy0 * (1.0 + kRounding)) << "dissipative at |omega| dt <= 0.7 rad";
      } else if (integrator == Integrator::Newmark) {
        EXPECT_NEAR(body.state().angularMomentum.norm() / L0.norm(), 1.0, 1e-9) << "m " << masses[k] << " dt " << dt;
        EXPECT_LE(worstEnergyError, 1e-9) << "the midpoint keeps E, m " << masses[k] << " dt " << dt;
      } else {
        EXPECT_TRUE(body.state().angularMomentum == L0) << "m " << masses[k] << " dt " << dt;
      }
      // rk4 and dlm are at least second order: energy error (|omega0| dt)^2 / 4 covers the
      // measured figures with >= 3x margin; forward and symplectic Euler drift at first order.
      if (integrator == Integrator::Rk4 || integrator == Integrator::Dlm) {
        const double bound = 0.25 * std::pow(kSpin.norm() * dt, 2);
        EXPECT_LE(worstEnergyError, bound) << "m " << masses[k] << " dt " << dt;
      }
    }
    for (int k = 1; k < 3; ++k) {
      // Measured <= 2.2e-11 rad after 1000 steps; rounding differs, the physics may not.
      EXPECT_LE(rotationAngleBetween(rotation[0], rotation[k]), 1e-9) << "m " << masses[k] << " dt " << dt;
      EXPECT_NEAR(energyRatio[k], energyRatio[0], 1e-11 * energyRatio[0]) << "m " << masses[k] << " dt " << dt;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, StressMassAndStep, testing::ValuesIn(test::allIntegrators()),
                         test::integratorParamName);

TEST(StressTimeStep, OutsideTheAcceptedRangeTheWorldRefusesAndNamesDt) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double dt : {0.2, kMaxTimeStep * (1.0 + 1e-12), 1e-7, kMinTimeStep * (1.0 - 1e-12), 0.0, -0.01,
                    std::nan(""), inf, -inf}) {
    std::string message;
    try {
      World world = worldAt(Integrator::Dlm, dt, kGravity);
      ADD_FAILURE() << "dt = " << dt << " s was accepted";
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    std::ostringstream value;
    value << dt;
    EXPECT_EQ(message.rfind("world.dt: ", 0), 0u) << message;  // names the field first, as the scene loader does
    EXPECT_NE(message.find(value.str()), std::string::npos) << message;
  }
  for (double dt : {kMinTimeStep, kMaxTimeStep}) {
    World world = worldAt(Integrator::Dlm, dt, kGravity);
    world.addBody(bodyOf(1.0));
    world.step();
    EXPECT_TRUE(finiteAndUnit(world.bodies()[0])) << "dt " << dt;
  }
}

}  // namespace
}  // namespace rbsim
