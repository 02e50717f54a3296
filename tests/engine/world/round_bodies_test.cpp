// Worlds of spheres and capsules (issue 20's figures): a ball rolling without slipping keeps its
// kinetic energy, round bodies rest on each other and on their sides, a capsule lies still on a
// box, and a row of touching balls passes an elastic hit down the line. At dt = 1/60 s (what
// users pick) and 1/240 s, with both contact solvers.
#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "test_util.h"
#include "rbsim/body/shape_body.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using Solver = Settings::ContactSolverMethod;

struct RoundCase {
  double dt;
  Solver solver;
};

class RoundBodies : public testing::TestWithParam<RoundCase> {
 protected:
  // A World with the ground plane y = 0.
  Settings settings() const {
    Settings s;
    s.timeStep = GetParam().dt;
    s.solver = GetParam().solver;
    // PGS integrates before it solves (Catto 2005): these figures are its own with the
    // forward-Euler drift x += dt v it was tuned with; exact's drift carries g dt^2 / 2 more a
    // step, which PGS pushes back out (docs/integrators.md).
    if (s.solver == Settings::ContactSolverMethod::Pgs) s.integrator = Integrator::ExpMap;
    s.allowSleep = false;  // the figures are about the solver, not about sleeping
    return s;
  }
  int steps(double seconds) const { return static_cast<int>(std::lround(seconds / GetParam().dt)); }
};

// Issue 20: r = 0.5 m at 2 m/s with omega = v / r lost 87 % of its kinetic energy in 10 s as a
// 48 x 24 polyhedron. The exact sphere's contact point has zero velocity, so no impulse may do
// work on it: the energy stays to 1e-6 and the ball rolls 20 m.
TEST_P(RoundBodies, ABallRollingWithoutSlippingKeepsItsEnergy) {
  World w(settings());
  w.addPlane(Plane{});
  BodyDef ball = shapeBodyDef(Shape::sphere(0.5), 1.0, "ball");
  ball.position = Vec3(0.0, 0.5, 0.0);
  ball.velocity = Vec3(2.0, 0.0, 0.0);
  ball.angularVelocity = Vec3(0.0, 0.0, -2.0 / 0.5);  // omega x (-r e_y) = -v: the contact is still
  w.addBody(ball);
  const double e0 = w.bodies()[0].kineticEnergy();
  EXPECT_NEAR(e0, 0.5 * 4.0 + 0.5 * 0.1 * 16.0, 1e-12);  // 2.8 J, as in the issue
  for (int i = 0; i < steps(10.0); ++i) w.step();
  const RigidBody& b = w.bodies()[0];
  EXPECT_NEAR(b.kineticEnergy() / e0, 1.0, 1e-6);
  EXPECT_NEAR(b.position().x(), 20.0, 1e-4);
  EXPECT_NEAR(b.position().y(), 0.5, 0.006);  // within the solver's slop of resting
}

// A ball on a static ball, exactly above its centre: the normal is vertical at every step, so
// nothing tips it off (a polyhedron's facets would give a tilted normal whenever it turns).
TEST_P(RoundBodies, ABallRestsOnABall) {
  World w(settings());
  w.addPlane(Plane{});
  BodyDef base = shapeBodyDef(Shape::sphere(0.5), 1.0, "base");
  base.position = Vec3(0.0, 0.5, 0.0);
  base.isStatic = true;
  w.addBody(base);
  BodyDef top = shapeBodyDef(Shape::sphere(0.3), 1.0, "top");
  top.position = Vec3(0.0, 1.3, 0.0);
  top.angularVelocity = Vec3(0.0, 5.0, 0.0);  // spinning about the vertical, which must not tip it
  w.addBody(top);
  for (int i = 0; i < steps(5.0); ++i) w.step();
  const RigidBody& b = w.bodies()[1];
  EXPECT_LT(std::hypot(b.position().x(), b.position().z()), 1e-9);
  EXPECT_NEAR(b.position().y(), 1.3, 0.006);
  EXPECT_LT(b.velocity().norm(), 1e-3);
}

// A capsule dropped on its side settles on both caps, axis level, and stays put.
TEST_P(RoundBodies, ACapsuleRestsOnItsSide) {
  World w(settings());
  w.addPlane(Plane{});
  BodyDef c = shapeBodyDef(Shape::capsule(0.2, 0.5), 2.0, "capsule");
  c.position = Vec3(0.0, 0.3, 0.0);
  c.orientation = quatFromAxisAngle(Vec3(0.0, 0.0, 0.5 * kPi));
  w.addBody(c);
  for (int i = 0; i < steps(3.0); ++i) w.step();
  const RigidBody& b = w.bodies()[0];
  EXPECT_NEAR(b.position().y(), 0.2, 0.006);
  EXPECT_LT(std::abs(b.rotation().col(1).y()), 1e-6);  // the axis stays level
  EXPECT_LT(b.velocity().norm() + b.angularVelocity().norm(), 1e-3);
  EXPECT_LT(std::abs(b.position().x()) + std::abs(b.position().z()), 1e-6);
  ASSERT_EQ(w.contacts().size(), 1u);
  EXPECT_EQ(w.contacts()[0].manifold.count, 2);  // one point under each cap
}

// A capsule laid across a box rests on it at two points and does not roll off.
TEST_P(RoundBodies, ACapsuleRestsAcrossABox) {
  World w(settings());
  w.addPlane(Plane{});
  BodyDef box = shapeBodyDef(Shape::box(Vec3(0.5, 0.25, 0.5)), 4.0, "box");
  box.position = Vec3(0.0, 0.25, 0.0);
  w.addBody(box);
  BodyDef c = shapeBodyDef(Shape::capsule(0.1, 0.3), 1.0, "capsule");
  c.position = Vec3(0.1, 0.6, 0.0);
  c.orientation = quatFromAxisAngle(Vec3(0.5 * kPi, 0.0, 0.0));
  w.addBody(c);
  for (int i = 0; i < steps(3.0); ++i) w.step();
  const RigidBody& b = w.bodies()[1];
  EXPECT_NEAR(b.position().y(), 0.6, 0.012);  // two contacts' slop
  // It may roll a little while the box under it settles into the slop, no more than 1 mm.
  EXPECT_NEAR(b.position().x(), 0.1, 1e-3);
  EXPECT_LT(b.velocity().norm() + b.angularVelocity().norm(), 1e-3);
}

// Newton's cradle without strings: five balls in a row, touching, no gravity, restitution 1 and
// no friction; the first arrives at 1 m/s. The seed's law u_N' = -c_R u_N (the restitution
// threshold off, world.restitution_threshold = 0) applied contact by contact down the line hands
// the whole momentum on: the last ball leaves at 1 m/s and the others stay, within the solver's
// tolerance (5 % of the speed). The hit comes at a step's end (the first ball 5 cm short of
// 0.2 m away) and within one (1.2 mm further): there the soft step's substeps used to meet it as
// an inelastic push through the row, and the last ball left at 0.52 m/s (issue 55).
TEST_P(RoundBodies, NewtonsCradlePassesAnElasticHitDownTheLine) {
  if (GetParam().solver == Solver::Pgs) {
    GTEST_SKIP() << "PGS solves the row's contacts together: the five leave at 0.42 m/s and less (REPORT)";
  }
  Settings s = settings();
  s.gravity = Vec3::Zero();
  s.restitutionThreshold = 0.0;
  constexpr double r = 0.1, speed = 1.0;
  Material elastic;
  elastic.restitution = 1.0;
  elastic.staticFriction = elastic.kineticFriction = 0.0;
  for (const double away : {0.05, 0.0512}) {  // [m]
    World w(s);
    for (int i = 0; i < 5; ++i) {
      BodyDef ball = shapeBodyDef(Shape::sphere(r), 1.0, "ball" + std::to_string(i));
      ball.position = Vec3(i == 0 ? -2.0 * r - away : 2.0 * r * i, 0.0, 0.0);
      ball.velocity = Vec3(i == 0 ? speed : 0.0, 0.0, 0.0);
      ball.material = elastic;
      w.addBody(ball);
    }
    for (int i = 0; i < steps(0.5); ++i) w.step();
    const auto& b = w.bodies();
    EXPECT_NEAR(b[4].velocity().x(), speed, 0.05 * speed) << "first ball " << away << " m short";
    for (int i = 0; i < 4; ++i) EXPECT_LT(b[i].velocity().norm(), 0.05 * speed) << i << ", " << away << " m short";
    double momentum = 0.0, energy = 0.0;
    for (const RigidBody& ball : b) momentum += ball.state().linearMomentum.x(), energy += ball.kineticEnergy();
    EXPECT_NEAR(momentum, speed, 1e-9);  // the solver's impulses are equal and opposite
    EXPECT_NEAR(energy, 0.5 * speed * speed, 0.05 * 0.5 * speed * speed);
  }
}

INSTANTIATE_TEST_SUITE_P(DtAndSolver, RoundBodies,
                         testing::Values(RoundCase{1.0 / 60.0, Solver::SoftStep}, RoundCase{1.0 / 240.0, Solver::SoftStep},
                                         RoundCase{1.0 / 60.0, Solver::Pgs}, RoundCase{1.0 / 240.0, Solver::Pgs}),
                         [](const testing::TestParamInfo<RoundCase>& info) {
                           return std::string(info.param.solver == Solver::Pgs ? "Pgs" : "SoftStep") + "_" +
                                  std::to_string(static_cast<int>(std::lround(1.0 / info.param.dt))) + "Hz";
                         });

}  // namespace
}  // namespace rbsim
