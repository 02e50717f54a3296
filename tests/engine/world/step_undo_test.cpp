// A step that fails is undone (issue 56, item 6; world/step_undo.cpp): after the SimulationError
// the World reads as before the step, bit for bit, and once the cause is taken away the next step
// is the step a World without the cause takes; with each solver's order and the integrators that
// keep state of their own (euler-matrix's raw R), at the time steps users pick.
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/ragdoll.h"
#include "rbsim/world/spawner.h"
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
  const SpringId wildSpring = addSpring(w, wild);
  const std::uint64_t hash = w.stateHash();
  const std::uint64_t steps = w.stepCount();
  EXPECT_THROW(w.step(), SimulationError);
  EXPECT_EQ(w.stateHash(), hash);
  EXPECT_EQ(w.stepCount(), steps);
  EXPECT_THROW(w.step(), SimulationError);  // the same step fails the same way: nothing compounds
  EXPECT_EQ(w.stateHash(), hash);
  removeSpring(w, wildSpring);
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

// A failing step that spawns, ages bodies out and kills one: after the failure the World has the
// bodies it had, under the same ids and names, the spawner's next burst is still due, and the
// retry without the cause is the twin's step, the spawns and removals made once.
TEST_P(StepUndo, AFailedStepThatSpawnsAndRemovesLeavesTheBodiesAsTheyWere) {
  World w = flyingWorld(GetParam());
  const double dt = w.settings().timeStep;
  SpawnerDef spawn;
  spawn.name = "rain";
  spawn.prototype = shapeBodyDef(Shape::box(Vec3(0.1, 0.1, 0.1)), 1.0, "drop");
  spawn.count = 2;
  spawn.start = w.time();
  spawn.period = 2.0 * dt;
  spawn.lifetime = 2.0 * dt;  // each burst is removed as the next is made
  spawn.regionMin = Vec3(-1, 20, -1);
  spawn.regionMax = Vec3(1, 21, 1);
  spawn.seed = 7;
  addSpawner(w, spawn);
  setKillVolume(w, Aabb{Vec3(-100, 9.8, -100), Vec3(100, 100, 100)});  // b0..b2 fly up from y = 10
  for (int i = 0; i < 2; ++i) w.step();  // steps 11 and 12: a burst, then nothing
  const World without = w;
  Spring wild;
  wild.body = w.idAt(1);
  wild.anchor = Vec3(0, -1e6, 0);
  wild.stiffness = std::numeric_limits<double>::max();
  const SpringId wildSpring = addSpring(w, wild);
  const auto names = [](const World& world) {
    std::vector<std::string> out;
    for (const RigidBody& b : world.bodies()) out.push_back(b.name());
    return out;
  };
  const std::vector<std::string> namesBefore = names(w);
  std::vector<BodyId> idsBefore;
  for (std::size_t i = 0; i < w.bodies().size(); ++i) idsBefore.push_back(w.idAt(i));
  const std::uint64_t hash = w.stateHash();
  ASSERT_EQ(w.bodies().size(), 5u);  // b0..b2 and the first burst of two
  EXPECT_THROW(w.step(), SimulationError);  // would age out the burst, make the next, kill none yet
  EXPECT_EQ(names(w), namesBefore);
  for (std::size_t i = 0; i < w.bodies().size(); ++i) EXPECT_EQ(w.idAt(i), idsBefore[i]) << i;
  EXPECT_EQ(w.stateHash(), hash);
  EXPECT_TRUE(spawnedBodies(w).empty()) << "the lists of the last step that stood (none)";
  EXPECT_TRUE(removedBodies(w).empty());
  removeSpring(w, wildSpring);
  World twin = without;
  const int steps = static_cast<int>(std::ceil(0.7 / dt));  // b0..b2 fall below 9.8 m by 0.5 s
  for (int i = 0; i < steps; ++i) {  // the retry, then on until the kill volume has taken bodies too
    w.step();
    twin.step();
    ASSERT_EQ(names(w), names(twin)) << "step " << i;
    ASSERT_EQ(w.stateHash(), twin.stateHash()) << "step " << i;
  }
  EXPECT_LT(w.bodies().size(), 5u) << "the kill volume took some of b0..b2";
}

// A failing step that only spawns (a ragdoll and two boxes) is undone by removing what it made:
// the World is as before, ids and generations included, and the retry is the twin's step.
// (The soft step alone: PGS does not solve a ragdoll's joints, and refuses its spawner.)
class SoftStepUndo : public StepUndo {};

TEST_P(SoftStepUndo, AFailedStepThatOnlySpawnsLeavesTheBodiesAsTheyWere) {
  World w = flyingWorld(GetParam());
  const double dt = w.settings().timeStep;
  w.destroyBody(w.idAt(1));  // a free slot for the burst to take, whose generation must come back
  SpawnerDef boxes;
  boxes.name = "drop";
  boxes.prototype = shapeBodyDef(Shape::box(Vec3(0.1, 0.1, 0.1)), 1.0, "drop");
  boxes.count = 2;
  boxes.start = w.time() + dt;
  boxes.regionMin = Vec3(-1, 20, -1);
  boxes.regionMax = Vec3(1, 21, 1);
  addSpawner(w, boxes);
  SpawnerDef figures = boxes;
  figures.name = "figure";
  figures.count = 1;
  figures.ragdoll = RagdollDef{};
  addSpawner(w, figures);
  w.step();  // nothing due yet
  const World without = w;
  Spring wild;
  wild.body = w.idAt(0);
  wild.anchor = Vec3(0, -1e6, 0);
  wild.stiffness = std::numeric_limits<double>::max();
  const SpringId wildSpring = addSpring(w, wild);
  const std::size_t bodies = w.bodies().size(), joints = w.joints().size();
  const std::uint64_t hash = w.stateHash();
  EXPECT_THROW(w.step(), SimulationError);
  EXPECT_EQ(w.bodies().size(), bodies);
  EXPECT_EQ(w.joints().size(), joints);
  EXPECT_EQ(w.stateHash(), hash);
  removeSpring(w, wildSpring);
  World twin = without;
  for (int i = 0; i < 5; ++i) {
    w.step();
    twin.step();
    ASSERT_EQ(w.bodies().size(), twin.bodies().size()) << "step " << i;
    for (std::size_t k = 0; k < w.bodies().size(); ++k) {
      ASSERT_EQ(w.idAt(k), twin.idAt(k)) << "step " << i << ", body " << k;
      ASSERT_EQ(w.bodies()[k].name(), twin.bodies()[k].name()) << "step " << i << ", body " << k;
    }
    ASSERT_EQ(w.stateHash(), twin.stateHash()) << "step " << i;
  }
  EXPECT_EQ(w.bodies().size(), bodies + 2 + kBoneCount) << "the retry made the burst once";
}

INSTANTIATE_TEST_SUITE_P(
    SolversAndIntegrators, StepUndo,
    testing::Combine(testing::Values(Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs),
                     testing::Values(Integrator::EulerMatrix, Integrator::EulerQuat, Integrator::Rk4),
                     testing::Values(1.0 / 60.0, 1.0 / 240.0)));
INSTANTIATE_TEST_SUITE_P(
    Integrators, SoftStepUndo,
    testing::Combine(testing::Values(Settings::ContactSolverMethod::SoftStep),
                     testing::Values(Integrator::EulerMatrix, Integrator::EulerQuat, Integrator::Rk4),
                     testing::Values(1.0 / 60.0, 1.0 / 240.0)));

}  // namespace
}  // namespace rbsim
