// Kinematic bodies (seed 000's infinite-mass objects, K = 0): a platform moved by its prescribed
// velocity carries and lifts the boxes on it, and nothing that hits it changes its motion. With
// both contact solvers, at dt = 1/60 s and 1/240 s.
#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using Solver = Settings::ContactSolverMethod;

struct KinematicCase {
  double dt;
  Solver solver;
};

class Kinematic : public testing::TestWithParam<KinematicCase> {
 protected:
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam().dt;
    s.solver = GetParam().solver;
    // PGS integrates before it solves (Catto 2005): these figures are its own with the
    // forward-Euler drift x += dt v it was tuned with; exact's drift carries g dt^2 / 2 more a
    // step, which PGS pushes back out (docs/integrators.md).
    if (s.solver == Settings::ContactSolverMethod::Pgs) s.integrator = Integrator::ExpMap;
    return s;
  }
  int steps(double seconds) const { return static_cast<int>(std::lround(seconds / GetParam().dt)); }

  static BodyDef platform(const Vec3& velocity) {
    BodyDef def = shapeBodyDef(Shape::box(Vec3(2.0, 0.1, 2.0)), 10.0, "platform");
    def.isKinematic = true;
    def.position = Vec3(0.0, 1.0, 0.0);
    def.velocity = velocity;
    return def;
  }
  static BodyDef boxOn(double platformTop) {
    BodyDef def = shapeBodyDef(Shape::box(Vec3(0.25, 0.25, 0.25)), 1.0, "box");
    def.position = Vec3(0.0, platformTop + 0.25, 0.0);
    return def;
  }
};

// A platform starting to glide at 1 m/s under a box at rest: the box slides on it, accelerated by
// kinetic friction at mu_k g (mu_k = 0.5, the default material), until it has the platform's
// speed, then rides along: it ends v^2 / (2 mu_k g) = 0.102 m behind where it started on it.
TEST_P(Kinematic, APlatformCarriesABoxAlong) {
  World w(settings());
  const Vec3 speed(1.0, 0.0, 0.0);
  w.addBody(platform(speed));
  w.addBody(boxOn(1.1));
  for (int i = 0; i < steps(2.0); ++i) w.step();
  const RigidBody& p = w.bodies()[0];
  const RigidBody& box = w.bodies()[1];
  EXPECT_NEAR(p.position().x(), 2.0, 1e-12);  // exactly where it was sent, gravity or not
  EXPECT_EQ(p.position().y(), 1.0);
  EXPECT_NEAR(box.velocity().x(), 1.0, 1e-3);
  const double lag = 1.0 / (2.0 * Material{}.kineticFriction * 9.81);
  EXPECT_NEAR(p.position().x() - box.position().x(), lag, 0.01);
  EXPECT_NEAR(box.position().y(), 1.35, 0.006);                   // resting on the top face
}

// A platform rising at 0.5 m/s lifts the box: the box rises with it, and it never sinks in.
TEST_P(Kinematic, APlatformLiftsABox) {
  World w(settings());
  w.addBody(platform(Vec3(0.0, 0.5, 0.0)));
  w.addBody(boxOn(1.1));
  for (int i = 0; i < steps(2.0); ++i) w.step();
  const RigidBody& p = w.bodies()[0];
  const RigidBody& box = w.bodies()[1];
  EXPECT_NEAR(p.position().y(), 2.0, 1e-12);
  EXPECT_NEAR(box.position().y() - p.position().y(), 0.35, 0.006);
  EXPECT_NEAR(box.velocity().y(), 0.5, 0.01);
}

// A heavy ball thrown at a resting kinematic wall bounces off; the wall does not move.
TEST_P(Kinematic, NothingThatHitsItMovesIt) {
  Settings s = settings();
  s.gravity = Vec3::Zero();
  World w(s);
  BodyDef wall = platform(Vec3::Zero());
  wall.angularVelocity = Vec3(0.0, 0.3, 0.0);  // turning slowly about its vertical axis
  w.addBody(wall);
  BodyDef ball = shapeBodyDef(Shape::sphere(0.2), 100.0, "ball");
  ball.position = Vec3(0.0, 2.0, 0.0);
  ball.velocity = Vec3(0.0, -3.0, 0.0);
  w.addBody(ball);
  for (int i = 0; i < steps(1.0); ++i) w.step();
  const RigidBody& p = w.bodies()[0];
  EXPECT_EQ(p.position(), Vec3(0.0, 1.0, 0.0));
  EXPECT_NEAR(p.angularVelocity().y(), 0.3, 1e-12);
  EXPECT_LT(p.velocity().norm(), 1e-12);
  EXPECT_GT(w.bodies()[1].velocity().y(), -1e-6);  // stopped or sent back, not through
  EXPECT_GT(w.bodies()[1].position().y(), 1.1 + 0.2 - 0.01);
}

INSTANTIATE_TEST_SUITE_P(DtAndSolver, Kinematic,
                         testing::Values(KinematicCase{1.0 / 60.0, Solver::SoftStep}, KinematicCase{1.0 / 240.0, Solver::SoftStep},
                                         KinematicCase{1.0 / 60.0, Solver::Pgs}, KinematicCase{1.0 / 240.0, Solver::Pgs}),
                         [](const testing::TestParamInfo<KinematicCase>& info) {
                           return std::string(info.param.solver == Solver::Pgs ? "Pgs" : "SoftStep") + "_" +
                                  std::to_string(static_cast<int>(std::lround(1.0 / info.param.dt))) + "Hz";
                         });

TEST(Kinematic, StaticAndKinematicAtOnceIsRefused) {
  BodyDef def = shapeBodyDef(Shape::sphere(1.0), 1.0);
  def.isStatic = def.isKinematic = true;
  EXPECT_THROW(RigidBody{def}, std::invalid_argument);
}

}  // namespace
}  // namespace rbsim
