// integrate: seed 004's matrix update R += dt omega* R, with its "Drift correction" (the default)
// and without it (Settings::driftCorrection = false). Without it the World keeps the raw matrix:
// every step multiplies R by I + dt omega*, whose determinant is 1 + dt^2 |omega|^2, so det R grows
// by exactly that factor a step and the drawn vertices R p + x shear and grow; with it R stays a
// rotation to rounding.
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/integrate/integrator.h"
#include "rbsim/math/rotation.h"
#include "rbsim/settings/settings.h"
#include "rbsim/world/world.h"
#include "test_util.h"

namespace rbsim {
namespace {

World spinningBrick(double dt, bool driftCorrection) {
  Settings s;
  s.integrator = Integrator::EulerMatrix;
  s.driftCorrection = driftCorrection;
  s.timeStep = dt;
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef def = test::boxDef(Vec3(1.0, 0.5, 0.3), 2.0, "brick");
  def.position = Vec3(0.2, 1.2, -0.4);
  def.angularVelocity = Vec3(0.4, 2.0, 0.8);  // about no principal axis: omega changes as it turns
  world.addBody(def);
  return world;
}

class DriftCorrection : public testing::TestWithParam<double> {};

// The World's raw R follows R_{n+1} = R_n + dt omega_n* R_n with omega_n = R_n I_body^-1 R_n^T L,
// as seed 004 computes it, step for step; its determinant is the product of 1 + dt^2 |omega_n|^2.
TEST_P(DriftCorrection, WithoutItRIsTheSeedsRawMatrixAndItsDeterminantGrowsAsPredicted) {
  const double dt = GetParam();
  World world = spinningBrick(dt, false);
  const RigidBody& body = world.bodies()[0];
  const Vec3 L = body.state().angularMomentum;
  const Mat3 inverseInertiaBody = body.inverseInertiaBody();
  Mat3 R = body.rotation();
  double determinant = 1.0;
  const int steps = static_cast<int>(std::lround(2.0 / dt));  // 2 s
  for (int n = 0; n < steps; ++n) {
    const Vec3 omega = R * inverseInertiaBody * R.transpose() * L;
    ASSERT_LT((body.angularVelocity() - omega).norm(), 1e-9 * omega.norm()) << "step " << n;
    determinant *= 1.0 + dt * dt * omega.squaredNorm();
    R = R + dt * star(omega) * R;
    world.step();
  }
  EXPECT_LT((body.rotation() - R).norm(), 1e-9);
  EXPECT_NEAR(body.rotation().determinant(), determinant, 1e-9 * determinant);
  EXPECT_GT(determinant, 1.0 + 0.5 * steps * dt * dt * 4.0);  // |omega| >= 2 rad/s throughout
  EXPECT_GT(orthonormalityError(body.rotation()), 1e-3);  // the drift the seed warns of
  // The vertices the program computes are R p + x with this very matrix: the box is drawn sheared.
  const std::vector<Vec3>& world_vertices = body.worldVertices();
  for (std::size_t i = 0; i < world_vertices.size(); ++i) {
    EXPECT_LT((world_vertices[i] - (R * body.bodyVertex(i) + body.position())).norm(), 1e-9);
  }
  // q is R's nearest rotation: a unit quaternion, within the drift of R.
  EXPECT_NEAR(body.orientation().norm(), 1.0, 1e-12);
}

TEST_P(DriftCorrection, WithItRStaysARotation) {
  const double dt = GetParam();
  World world = spinningBrick(dt, true);
  const int steps = static_cast<int>(std::lround(2.0 / dt));
  for (int n = 0; n < steps; ++n) world.step();
  const RigidBody& body = world.bodies()[0];
  EXPECT_LT(orthonormalityError(body.rotation()), 1e-12);
  EXPECT_NEAR(body.rotation().determinant(), 1.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, DriftCorrection, testing::Values(1.0 / 60.0, 1.0 / 240.0));

TEST(DriftCorrectionSetting, OffIsRefusedForAnIntegratorThatKeepsNoMatrix) {
  for (const std::string& name : integratorNames()) {
    Settings s;
    ASSERT_TRUE(parseIntegrator(name, s.integrator));
    s.driftCorrection = false;
    const SettingsProblem problem = checkSettings(s);
    EXPECT_EQ(static_cast<bool>(problem), s.integrator != Integrator::EulerMatrix) << name;
    if (problem) {
      EXPECT_EQ(problem.key, "drift_correction");
      EXPECT_THROW(World{s}, std::invalid_argument);
    }
  }
}

}  // namespace
}  // namespace rbsim
