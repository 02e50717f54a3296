// Issue 25: both friction models (world.friction = cone | seed000) with both solvers at 1/60 and
// 1/240 s against the analytic motion of a box (bench/friction_cases.h): sliding to a stop at
// v0^2 / (2 mu_k g), held on an incline below the friction angle atan(mu_s), sliding down a
// steeper one at g (sin theta - mu_k cos theta); and seed 000's restitution law
// u_N^+ = -c_R u_N with world.restitution_threshold = 0. Figures: REPORT section 5,
// build/bench/friction_models.
#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "friction_cases.h"

namespace rbsim {
namespace {

using bench::kCaseKineticFriction;
using bench::kCaseStaticFriction;
using bench::kFrictionG;
using Solver = Settings::ContactSolverMethod;
using Friction = Settings::FrictionModel;

struct FrictionCase {
  Solver solver;
  Friction friction;
  double dt;  // [s]
};

std::string caseName(const testing::TestParamInfo<FrictionCase>& info) {
  return std::string(info.param.solver == Solver::Pgs ? "Pgs" : "SoftStep") +
         (info.param.friction == Friction::Seed000 ? "Seed000" : "Cone") + (info.param.dt > 0.01 ? "At60" : "At240");
}

class FrictionModels : public testing::TestWithParam<FrictionCase> {
 protected:
  Settings settings() const { return bench::frictionCaseSettings(GetParam().solver, GetParam().friction, GetParam().dt); }
  // The discretisation's share of the error: at 1/60 s a slide ends up to 2.5 % long or short
  // (measured -2.1 % soft step, +2.7 % PGS), at 1/240 s within 0.7 %.
  double slideTolerance() const { return GetParam().dt > 0.01 ? 0.03 : 0.01; }
};

TEST_P(FrictionModels, ASlidingBoxStopsAtTheKineticDistance) {
  // mu_s in place of mu_k would stop it at 0.340 m instead of 0.408 m, 17 % short.
  const double v0 = 2.0;
  const double distance = v0 * v0 / (2.0 * kCaseKineticFriction * kFrictionG);
  const bench::SlideResult slide = bench::slideToStop(settings(), v0);
  EXPECT_NEAR(slide.distance / distance, 1.0, slideTolerance()) << slide.distance << " m";
  EXPECT_NEAR(slide.stopTime, v0 / (kCaseKineticFriction * kFrictionG), 0.03 * v0 / (kCaseKineticFriction * kFrictionG) + GetParam().dt);
}

TEST_P(FrictionModels, ABoxStaysOnAnInclineBelowTheFrictionAngle) {
  // atan(mu_s) = 30.96 degrees; mu_k alone would let it slide from 26.57 degrees.
  for (const double degrees : {25.0, 28.0, 30.0}) {
    EXPECT_LT(std::abs(bench::incline(settings(), degrees, 10.0).slide), 1e-3) << degrees << " degrees";
  }
}

TEST_P(FrictionModels, ABoxSlidesDownASteeperInclineAtTheKineticAcceleration) {
  // At 40 degrees mu_s would give 1.79 m/s^2 instead of 2.55.
  for (const double degrees : {32.0, 40.0}) {
    const double theta = degrees * M_PI / 180.0;
    const double expected = kFrictionG * (std::sin(theta) - kCaseKineticFriction * std::cos(theta));
    EXPECT_NEAR(bench::incline(settings(), degrees, 1.0).acceleration, expected, 0.01 * expected) << degrees << " degrees";
  }
  static_assert(kCaseKineticFriction < kCaseStaticFriction, "the cases tell mu_s from mu_k");
}

INSTANTIATE_TEST_SUITE_P(BothSolversBothSteps, FrictionModels,
                         testing::Values(FrictionCase{Solver::SoftStep, Friction::Cone, 1.0 / 60.0},
                                         FrictionCase{Solver::SoftStep, Friction::Cone, 1.0 / 240.0},
                                         FrictionCase{Solver::SoftStep, Friction::Seed000, 1.0 / 60.0},
                                         FrictionCase{Solver::SoftStep, Friction::Seed000, 1.0 / 240.0},
                                         FrictionCase{Solver::Pgs, Friction::Cone, 1.0 / 60.0},
                                         FrictionCase{Solver::Pgs, Friction::Cone, 1.0 / 240.0},
                                         FrictionCase{Solver::Pgs, Friction::Seed000, 1.0 / 60.0},
                                         FrictionCase{Solver::Pgs, Friction::Seed000, 1.0 / 240.0}),
                         caseName);

// Seed 000 "Friction" for one collision (issue 55): a ball (m = 1 kg, R = 0.1 m) hits the ground
// at u = (vx, -3, 0) m/s, c_R = 0.5, mu_s = 0.6, mu_k = 0.2, no gravity. The seed's sticking
// impulse K_T^-1 (-c_R u_N N - u) = (-vx / 3.5, 4.5, 0) N s (K_T = diag(3.5, 1, 3.5) / kg at the
// contact) is inside the cone while vx / 3.5 <= 0.6 x 4.5, so at vx = 6 m/s the ball leaves
// rolling at 5/7 vx; at vx = 12 m/s it is kinetic, j = 4.5 (N - 0.2 T): vx drops by 0.9 to
// 11.1 m/s and omega_z = (r x j)_z / I = -22.5 rad/s. Coulomb's law for one impulse, so both
// models give it, and it must not depend on where in a step the ball meets the ground: it starts
// 0 to 49 mm above it (at 1/60 s it falls 50 mm a step), with the default continuous collision.
class ObliqueImpact : public testing::TestWithParam<FrictionCase> {
 protected:
  RigidBody afterTheBounce(double vx, double gap) const {
    Settings s;
    s.timeStep = GetParam().dt;
    s.solver = GetParam().solver;
    s.friction = GetParam().friction;
    s.gravity = Vec3::Zero();
    s.allowSleep = false;
    const Material material{0.5, 0.6, 0.2};
    World world(s);
    world.addPlane(Plane{}, material);
    BodyDef ball = shapeBodyDef(Shape::sphere(0.1), 1.0, "ball");
    ball.material = material;
    ball.position = Vec3(0.0, 0.1 + gap, 0.0);
    ball.velocity = Vec3(vx, -3.0, 0.0);
    const BodyId id = world.addBody(ball);
    for (double t = 0.0; t < 0.2; t += s.timeStep) world.step();  // it has left by 0.03 s
    return world.body(id);
  }
  static constexpr std::array<double, 6> kGaps{0.0, 0.001, 0.005, 0.02, 0.035, 0.049};  // [m]
};

TEST_P(ObliqueImpact, KineticThroughTheImpactAtAnyGap) {
  for (const double gap : kGaps) {
    const RigidBody ball = afterTheBounce(12.0, gap);
    EXPECT_NEAR(ball.velocity().x(), 11.1, 0.01 * 11.1) << "gap " << gap;
    EXPECT_NEAR(ball.velocity().y(), 1.5, 0.01 * 1.5) << "gap " << gap;
    EXPECT_NEAR(ball.angularVelocity().z(), -22.5, 0.01 * 22.5) << "gap " << gap;
  }
}

TEST_P(ObliqueImpact, LeavesRollingAtAnyGap) {
  for (const double gap : kGaps) {
    const RigidBody ball = afterTheBounce(6.0, gap);
    EXPECT_NEAR(ball.velocity().x(), 6.0 * 5.0 / 7.0, 0.01 * 6.0 * 5.0 / 7.0) << "gap " << gap;
    EXPECT_NEAR(ball.velocity().y(), 1.5, 0.01 * 1.5) << "gap " << gap;
    EXPECT_LT(std::abs(ball.velocity().x() + 0.1 * ball.angularVelocity().z()), 1e-3) << "slip at the contact, gap " << gap;
  }
}

INSTANTIATE_TEST_SUITE_P(BothSolversBothModelsBothSteps, ObliqueImpact,
                         testing::Values(FrictionCase{Solver::SoftStep, Friction::Seed000, 1.0 / 60.0},
                                         FrictionCase{Solver::SoftStep, Friction::Seed000, 1.0 / 240.0},
                                         FrictionCase{Solver::SoftStep, Friction::Cone, 1.0 / 60.0},
                                         FrictionCase{Solver::SoftStep, Friction::Cone, 1.0 / 240.0},
                                         FrictionCase{Solver::Pgs, Friction::Seed000, 1.0 / 60.0},
                                         FrictionCase{Solver::Pgs, Friction::Seed000, 1.0 / 240.0},
                                         FrictionCase{Solver::Pgs, Friction::Cone, 1.0 / 60.0},
                                         FrictionCase{Solver::Pgs, Friction::Cone, 1.0 / 240.0}),
                         caseName);

class RestitutionLaw : public testing::TestWithParam<FrictionCase> {};

// Seed 000 and 001: the body leaves at c_R times its speed at the touch, sqrt(2 g h), measured
// from its energy after the bounce (friction_cases.h): within 2.5 % for every case but one. Two used to
// miss it (issue 36): soft step's box from 1 m at 1/60 s left 7 % slow, its patch held to the gap
// by the last relax sweep a step before the touch; PGS's c_R = 0.3 from 1 cm left 58-137 % fast,
// reversed up to |u| dt above the ground. Both solvers now let such an approach on to the touch.
TEST_P(RestitutionLaw, TheBodyLeavesAtCrTimesItsImpactSpeed) {
  const Settings s = bench::restitutionSettings(GetParam().solver, GetParam().dt);
  for (const double restitution : {0.3, 0.7, 1.0}) {
    for (const double height : {0.01, 1.0}) {
      for (const bool ball : {false, true}) {
        const bench::BounceResult r = bench::dropAndBounce(s, restitution, height, ball);
        const double ratio = r.leaveSpeed / (restitution * r.impactSpeed);
        const std::string where = std::string(ball ? "ball" : "box") + ", c_R " + std::to_string(restitution) +
                                  ", from " + std::to_string(height) + " m";
        // The slowest bounce at 1/60 s (c_R 0.3 from 1 cm: 0.13 m/s, 0.9 mm up) leaves 4.5 % slow:
        // the soft step takes it at the substep of the touch (issue 55), and the substeps left
        // move it up g h t / 2 short of the exact flight, 0.1 mm (at the step's end it was 1.4 %).
        const bool slowest = GetParam().dt > 0.01 && restitution * r.impactSpeed < 0.2;
        EXPECT_NEAR(ratio, 1.0, slowest ? 0.05 : 0.025) << where;
      }
    }
  }
}

// The default threshold keeps a slow approach from bouncing: c_R = 1 from 1 cm (0.44 m/s) does
// not leave the ground, from 1 m (4.4 m/s) it does.
TEST_P(RestitutionLaw, TheDefaultThresholdStopsSlowApproaches) {
  Settings s = bench::restitutionSettings(GetParam().solver, GetParam().dt);
  s.restitutionThreshold = Settings{}.restitutionThreshold;
  EXPECT_LT(bench::dropAndBounce(s, 1.0, 0.01, true).leaveSpeed, 0.05);
  const bench::BounceResult fast = bench::dropAndBounce(s, 1.0, 1.0, true);
  EXPECT_NEAR(fast.leaveSpeed / fast.impactSpeed, 1.0, 0.025);
}

INSTANTIATE_TEST_SUITE_P(BothSolversBothSteps, RestitutionLaw,
                         testing::Values(FrictionCase{Solver::SoftStep, Friction::Cone, 1.0 / 60.0},
                                         FrictionCase{Solver::SoftStep, Friction::Cone, 1.0 / 240.0},
                                         FrictionCase{Solver::Pgs, Friction::Cone, 1.0 / 60.0},
                                         FrictionCase{Solver::Pgs, Friction::Cone, 1.0 / 240.0}),
                         caseName);

}  // namespace
}  // namespace rbsim
