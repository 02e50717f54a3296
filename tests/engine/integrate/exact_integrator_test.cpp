// integrate/integrator: exact and exact4 through World. Without torque both are the exact flow
// (checked against the independent reference over 20 s at a game time step); with torque, fixed
// in the world or in the body, their observed orders are 2 and 4 against world-frame RK4 at a
// step 100x finer. dlm's Strang kicks turn a body torque too: order 2.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/integrate/integrator.h"
#include "rbsim/math/rotation.h"
#include "reference/torque_free.h"
#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

// The case: a 1.0 x 0.3 x 0.1 m box of 1 kg spun at (0.01, 10, 0) rad/s, very near its
// intermediate axis (exact flip interval 2.0049 s), 20 s at 1/60 s.
const Vec3 kExtents(1.0, 0.3, 0.1);  // [m]
const Vec3 kOmega(0.01, 10.0, 0.0);  // [rad/s], body frame
const Mat3 kR0 = rotationFromAxisAngle(Vec3(0.3, -0.2, 0.5));

World tumbler(Integrator integrator, double dt, const Vec3& omegaBody = kOmega) {
  World world = test::worldWith(integrator, dt, Vec3(0.0, -9.81, 0.0));  // gravity: no torque
  BodyDef def = test::boxDef(kExtents, 1.0, "tumbler");
  def.orientation = Quat(kR0);
  def.angularVelocity = kR0 * omegaBody;
  world.addBody(def);
  return world;
}

class TorqueFreeExact : public testing::TestWithParam<Integrator> {};

TEST_P(TorqueFreeExact, FollowsTheExactSolutionFor20SecondsAtSixtyHertz) {
  World world = tumbler(GetParam(), 1.0 / 60.0);
  const RigidBody& body = world.bodies()[0];
  const reference::TorqueFreeExact exact(body.principalMoments(), kOmega, kR0);
  const auto spinEnergy = [&body] { return 0.5 * body.state().angularMomentum.dot(body.angularVelocity()); };
  const double energy0 = spinEnergy();
  const Vec3 L0 = body.state().angularMomentum;
  double worst = 0.0;
  for (int i = 1; i <= 1200; ++i) {
    world.step();
    if (i % 10 == 0) worst = std::max(worst, rotationAngleBetween(exact.rotation(world.time()), body.rotation()));
  }
  char recorded[32];
  std::snprintf(recorded, sizeof recorded, "%.3e", worst);
  RecordProperty("orientation_error", recorded);
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(spinEnergy(), energy0, 1e-12 * energy0);
  EXPECT_EQ(body.state().angularMomentum, L0);  // torque-free: L is never touched
}

INSTANTIATE_TEST_SUITE_P(ExactFamily, TorqueFreeExact, testing::Values(Integrator::Exact, Integrator::Exact4),
                         test::integratorParamName);

// A step that does not continue the last (a pose set by hand) restarts the flow from the new
// state: the motion is then the exact one from there.
TEST(ExactIntegrator, RestartsFromAStateSetByHand) {
  World world = tumbler(Integrator::Exact, 1.0 / 60.0);
  for (int i = 0; i < 60; ++i) world.step();
  const Quat turned = Quat(rotationFromAxisAngle(Vec3(0.0, 0.0, 1.0))) * world.bodies()[0].orientation();
  world.body(world.idAt(0)).setOrientation(turned.toRotationMatrix());
  const Vec3 omegaBody = world.bodies()[0].rotation().transpose() * world.bodies()[0].angularVelocity();
  const reference::TorqueFreeExact exact(world.bodies()[0].principalMoments(), omegaBody, turned.toRotationMatrix());
  const double t0 = world.time();
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_LT(rotationAngleBetween(exact.rotation(world.time() - t0), world.bodies()[0].rotation()), 1e-10);
}

enum class TorqueFrame { World, Body };

// A couple of two opposite forces 0.2 m either side of the centre: no net force, torque
// 2 r x f. In the world frame with world points, the torque stays fixed in the world (x does not
// move); in the body frame it turns with the body.
World torqued(Integrator integrator, double dt, TorqueFrame frame) {
  World world = tumbler(integrator, dt, Vec3(0.3, 4.0, -0.5));
  const Vec3 r(0.2, 0.0, 0.0), f(0.0, 0.05, 0.08);  // [m], [N]
  for (double sign : {1.0, -1.0}) {
    ScriptedForce couple;
    couple.body = world.idAt(0);
    couple.force = sign * f;
    couple.point = sign * r;
    couple.forceFrame = frame == TorqueFrame::World ? Frame::World : Frame::Body;
    couple.pointFrame = couple.forceFrame;
    couple.start = 0.0;
    couple.end = 1e9;
    world.addForce(couple);
  }
  return world;
}

Quat orientationAfter(Integrator integrator, double dt, TorqueFrame frame, double duration) {
  World world = torqued(integrator, dt, frame);
  const long steps = std::lround(duration / dt);
  for (long i = 0; i < steps; ++i) world.step();
  return world.bodies()[0].orientation();
}

struct OrderCase {
  Integrator integrator;
  int order;
  double dt;  // coarse step; the fine is dt / 2
};

class ObservedOrderWithTorque : public testing::TestWithParam<OrderCase> {};

TEST_P(ObservedOrderWithTorque, MatchesTheMethodsOrder) {
  const OrderCase c = GetParam();
  constexpr double kDuration = 2.0;  // [s]
  for (TorqueFrame frame : {TorqueFrame::World, TorqueFrame::Body}) {
    const Quat reference = orientationAfter(Integrator::Rk4, c.dt / 100.0, frame, kDuration);
    const double coarse = orientationAfter(c.integrator, c.dt, frame, kDuration).angularDistance(reference);
    const double fine = orientationAfter(c.integrator, c.dt / 2.0, frame, kDuration).angularDistance(reference);
    const double ratio = coarse / fine, expected = std::pow(2.0, c.order);
    std::printf("[ order ] %-8s torque in the %s frame, dt = 1/%.0f: %.3e rad, dt/2: %.3e rad, order %.2f\n",
                integratorName(c.integrator), frame == TorqueFrame::World ? "world" : "body", 1.0 / c.dt, coarse, fine,
                std::log2(ratio));
    EXPECT_GT(ratio, 0.8 * expected) << integratorName(c.integrator);
    EXPECT_LT(ratio, 1.25 * expected) << integratorName(c.integrator);
  }
}

INSTANTIATE_TEST_SUITE_P(Splitting, ObservedOrderWithTorque,
                         testing::Values(OrderCase{Integrator::Exact, 2, 1.0 / 50.0},
                                         OrderCase{Integrator::Exact4, 4, 1.0 / 25.0},
                                         OrderCase{Integrator::Dlm, 2, 1.0 / 50.0}),
                         [](const testing::TestParamInfo<OrderCase>& info) {
                           std::string name = integratorName(info.param.integrator);
                           return name;
                         });

}  // namespace
}  // namespace rbsim
