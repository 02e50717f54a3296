// A step that fails is undone (issue 56, item 6; world/step_undo.cpp): after the SimulationError
// the World reads as before the step, bit for bit, and once the cause is taken away the next step
// is the step a World without the cause takes; with each solver's order and the integrators that
// keep state of their own (euler-matrix's raw R), at the time steps users pick.
#include <limits>
#include <tuple>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/world.h"

namespace rbsim {
namespace {

using UndoCase = std::tuple<Settings::ContactSolverMethod, Integrator, double>;

class StepUndo : public testing::TestWithParam<UndoCase> {};

// Three bodies in free flight, spinning, one asleep; a pose event due at the failing step.
World flyingWorld(const UndoCase& c) {
  Settings s;
  s.solver = std::get<0>(c);
  s.integrator = std::get<1>(c);
  s.driftCorrection = s.integrator != Integrator::EulerMatrix;  // false: euler-matrix keeps its raw R
  s.timeStep = std::get<2>(c);
  s.gravity = Vec3(0, -9.81, 0);
  World w(s);
  for (int i = 0; i < 3; ++i) {
    BodyDef d = shapeBodyDef(Shape::box(Vec3(0.3 + 0.1 * i, 0.2, 0.1)), 1.0 + i, "b" + std::to_string(i));
    d.position = Vec3(3.0 * i, 10, 0);
    d.velocity = Vec3(1, 2, 0);
    d.angularVelocity = Vec3(0.5, 4.0 + i, 1.0);
    w.addBody(d);
  }
  PoseEvent nudge;
  nudge.body = w.idAt(0);
  nudge.time = 10 * s.timeStep;
  nudge.velocity = Vec3(0, 5, 0);
  w.addPoseEvent(nudge);
  for (int i = 0; i < 10; ++i) w.step();  // the next step applies the event
  w.body(w.idAt(2)).applyForce(Vec3(3, 0, 0));  // applied by hand before the step, as a user does
  return w;
}

TEST_P(StepUndo, AFailedStepLeavesTheWorldAsItWasAndARetryTakesTheStepWithoutTheCause) {
  World w = flyingWorld(GetParam());
  const World without = w;  // the same World, never given the cause
  // The cause: a spring no double holds (k |d| overflows), on body 1.
  Spring wild;
  wild.body = w.idAt(1);
  wild.anchor = Vec3(0, -1e6, 0);
  wild.stiffness = std::numeric_limits<double>::max();
  w.addSpring(wild);
  const std::uint64_t hash = w.stateHash();
  const std::uint64_t steps = w.stepCount();
  EXPECT_THROW(w.step(), SimulationError);
  EXPECT_EQ(w.stateHash(), hash);
  EXPECT_EQ(w.stepCount(), steps);
  EXPECT_THROW(w.step(), SimulationError);  // the same step fails the same way: nothing compounds
  EXPECT_EQ(w.stateHash(), hash);
  w.removeSpring(0);
  World twin = without;
  w.step();
  twin.step();
  ASSERT_EQ(w.bodies().size(), twin.bodies().size());
  for (std::size_t i = 0; i < w.bodies().size(); ++i) {
    const RigidBody& a = w.bodies()[i];
    const RigidBody& b = twin.bodies()[i];
    EXPECT_EQ(a.position(), b.position()) << i;
    EXPECT_EQ(a.orientation().coeffs(), b.orientation().coeffs()) << i;
    EXPECT_EQ(a.state().linearMomentum, b.state().linearMomentum) << i;
    EXPECT_EQ(a.state().angularMomentum, b.state().angularMomentum) << i;
    EXPECT_EQ(a.rotation(), b.rotation()) << i;
  }
  EXPECT_EQ(w.stateHash(), twin.stateHash());
  EXPECT_EQ(w.bodies()[0].velocity().y(), twin.bodies()[0].velocity().y());  // the event applied once, at the retry
}

INSTANTIATE_TEST_SUITE_P(
    SolversAndIntegrators, StepUndo,
    testing::Combine(testing::Values(Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs),
                     testing::Values(Integrator::EulerMatrix, Integrator::EulerQuat, Integrator::Rk4),
                     testing::Values(1.0 / 60.0, 1.0 / 240.0)));

}  // namespace
}  // namespace rbsim
