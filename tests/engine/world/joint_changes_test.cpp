// Changes of a running World's joints (world/joint_changes.h: setJointMotor, setJointLimits, removeJoint; issue
// 57): each acts from the next step, a refused one leaves the World as it was. At dt = 1/60 and
// 1/240 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/world/joint_changes.h"
#include "rbsim/world/joint_reading.h"
#include "rbsim/world/world.h"
#include "test_util.h"
#include "refusal.h"

namespace rbsim::test::joint_changes {
namespace {

constexpr double kG = 9.81;  // [m/s^2]

class JointChanges : public testing::TestWithParam<double> {
 protected:
  double dt() const { return GetParam(); }
  Settings settings(bool gravity = true) const {
    Settings s;
    s.timeStep = dt();
    s.gravity = gravity ? Vec3(0.0, -kG, 0.0) : Vec3::Zero();
    s.allowSleep = false;
    return s;
  }
  void run(World& world, double seconds) const {
    for (int i = 0; i < static_cast<int>(std::lround(seconds / dt())); ++i) world.step();
  }
};

// A wheel on a hinge about z to the world, its motor at 1 rad/s with torque to spare; changed to
// -2 rad/s, the hinge turns at -2 rad/s, and a tenth of a second later it is there.
TEST_P(JointChanges, MotorReachesTheNewTargetSpeed) {
  World world(settings(false));
  const BodyId wheel = world.addBody(boxDef(Vec3(0.5, 0.5, 0.1), 1.0, "wheel"));
  JointDef def;
  def.type = JointDef::Type::Hinge;
  def.bodyA = wheel;
  def.motor = true;
  def.motorSpeed = 1.0;
  def.maxMotorTorque = 100.0;  // [N m]: I = 0.04 kg m^2 turns 3 rad/s in about 1.2 ms
  const JointId joint = world.addJoint(def);
  run(world, 0.5);
  EXPECT_NEAR(readJoint(world, 0).speed, 1.0, 1e-6);
  setJointMotor(world, joint, true, -2.0, 100.0);
  EXPECT_EQ(world.joints()[0].def.motorSpeed, -2.0);
  run(world, 0.1);
  EXPECT_NEAR(readJoint(world, 0).speed, -2.0, 1e-6);
  // Off, the motor lets the wheel spin on freely at the speed it had.
  setJointMotor(world, joint, false, 0.0, 0.0);
  EXPECT_FALSE(world.joints()[0].def.motor);
  const double speed = readJoint(world, 0).speed;
  run(world, 0.2);
  EXPECT_NEAR(readJoint(world, 0).speed, speed, 1e-6);  // free: no torque, the spin keeps on
}

// A rod swinging on a hinge stops at limits set while it runs: |angle| stays within [-0.3, 0.3]
// (the soft step's slop) from the step after; removed, it swings past them again.
TEST_P(JointChanges, LimitsSetWhileRunningHoldTheAngle) {
  World world(settings(false));
  BodyDef rod = boxDef(Vec3(1.0, 0.1, 0.1), 1.0, "rod");
  rod.position = Vec3(0.5, 0.0, 0.0);
  rod.angularVelocity = Vec3(0.0, 0.0, 2.0);  // [rad/s]
  const BodyId id = world.addBody(rod);
  JointDef def;
  def.type = JointDef::Type::Hinge;
  def.bodyA = id;
  const JointId joint = world.addJoint(def);
  world.step();
  setJointLimits(world, joint, true, -0.3, 0.3);
  double most = 0.0;
  for (int i = 0; i < static_cast<int>(2.0 / dt()); ++i) {
    world.step();
    most = std::max(most, std::abs(readJoint(world, 0).angle));
  }
  EXPECT_LT(most, 0.3 + 0.01);
  setJointLimits(world, joint, false, 0.0, 0.0);
  // Turning about the pivot at 2 rad/s: omega and the centre's v = omega x (x - pivot) together.
  world.body(id).setAngularVelocity(Vec3(0.0, 0.0, 2.0));
  world.body(id).setVelocity(Vec3(0.0, 0.0, 2.0).cross(world.body(id).position()));
  run(world, 0.5);
  EXPECT_GT(std::abs(readJoint(world, 0).angle), 0.5);
}

// A box hanging at rest from a ball joint falls freely once the joint is removed: v = -g t and
// y = y0 - g t^2 / 2 (to the integrator's one-step offset, g t dt / 2). Of two joints, removing
// the first moves the second down to index 0.
TEST_P(JointChanges, RemovedJointLetsTheBodyFallFreely) {
  World world(settings());
  BodyDef box = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "box");
  box.position = Vec3(0.0, -0.5, 0.0);
  const BodyId id = world.addBody(box);
  BodyDef other = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "other");
  other.position = Vec3(3.0, -0.5, 0.0);
  const BodyId second = world.addBody(other);
  JointDef hang;
  hang.bodyA = id;
  const JointId first = world.addJoint(hang);
  hang.bodyA = second;
  hang.anchor = Vec3(3.0, 0.0, 0.0);
  hang.name = "second";
  world.addJoint(hang);
  run(world, 1.0);
  EXPECT_NEAR(world.body(id).position().y(), -0.5, 1e-3);  // hanging
  removeJoint(world, first);
  ASSERT_EQ(world.joints().size(), 1u);
  EXPECT_EQ(world.joints()[0].def.name, "second");
  EXPECT_TRUE(world.joints()[0].def.bodyA == second);
  const double y0 = world.body(id).position().y(), v0 = world.body(id).velocity().y();
  const int steps = static_cast<int>(0.5 / dt());
  for (int i = 0; i < steps; ++i) world.step();
  const double t = steps * dt();
  EXPECT_NEAR(world.body(id).velocity().y(), v0 - kG * t, 1e-9);
  EXPECT_NEAR(world.body(id).position().y(), y0 + v0 * t - 0.5 * kG * t * t, 0.5 * kG * t * dt() + 1e-9);
  EXPECT_NEAR(world.body(second).position().y(), -0.5, 1e-3);  // still hanging
}

// Jointed bodies do not collide; removing the joint lets them touch again from the next step.
TEST_P(JointChanges, RemovedJointsBodiesCollideAgain) {
  World world(settings(false));
  world.addBody(boxDef(Vec3(0.5, 0.5, 0.5), 1.0, "a"));
  BodyDef b = boxDef(Vec3(0.5, 0.5, 0.5), 1.0, "b");
  b.position = Vec3(0.45, 0.0, 0.0);
  world.addBody(b);
  JointDef def;
  def.bodyA = world.idAt(1);
  def.bodyB = world.idAt(0);
  def.anchor = Vec3(0.2, 0.0, 0.0);
  const JointId joint = world.addJoint(def);
  world.step();
  EXPECT_TRUE(world.contacts().empty());
  removeJoint(world, joint);
  world.step();
  EXPECT_FALSE(world.contacts().empty());
}

// Bad values are refused naming the call, the joint, the field and the expectation (the scene
// loader's words), and nothing changes: the state hash and the joint's definition.
TEST_P(JointChanges, BadValuesAreRefusedAndChangeNothing) {
  World world(settings());
  const BodyId a = world.addBody(boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "a"));
  JointDef hinge;
  hinge.type = JointDef::Type::Hinge;
  hinge.name = "elbow";
  hinge.bodyA = a;
  hinge.motor = true;
  hinge.motorSpeed = 1.0;
  hinge.maxMotorTorque = 5.0;
  const JointId elbow = world.addJoint(hinge);
  JointDef weld;
  weld.type = JointDef::Type::Weld;
  weld.bodyA = a;
  const JointId welded = world.addJoint(weld);
  world.step();
  const std::uint64_t hash = world.stateHash();
  const auto refused = [&](auto change, const std::string& words) {
    expectRefused(change, words);
    EXPECT_EQ(world.stateHash(), hash);
    ASSERT_EQ(world.joints().size(), 2u);
    const JointDef& d = world.joints()[0].def;
    EXPECT_TRUE(d.motor && d.motorSpeed == 1.0 && d.maxMotorTorque == 5.0 && !d.limits);
  };
  refused([&] { setJointMotor(world, elbow, true, 2e5, 5.0); },
          "setJointMotor: joint 0 ('elbow'): motor.speed: expected a speed of at most 100000 rad/s either way, got 200000");
  refused([&] { setJointMotor(world, elbow, true, 1.0, -5.0); }, "motor.max_torque: expected a torque from 0 to 1e+12 N m, got -5");
  refused([&] { setJointMotor(world, elbow, true, NAN, 5.0); }, "motor.speed: expected a speed of at most");
  refused([&] { setJointLimits(world, elbow, true, 1.0, -1.0); },
          "limits: expected [lower, upper] angles in radians with -pi <= lower <= upper <= pi");
  refused([&] { setJointLimits(world, elbow, true, -4.0, 0.0); }, "limits: expected [lower, upper] angles");
  refused([&] { setJointMotor(world, welded, true, 1.0, 5.0); }, "motor: a weld joint takes no motor");
  refused([&] { setJointLimits(world, welded, true, -1.0, 1.0); }, "limits: a weld joint takes no limits");
  const JointId never{2, 0};  // slot 2: no joint was ever made there
  refused([&] { setJointMotor(world, never, true, 1.0, 5.0); },
          "setJointMotor: joint id (slot 2, generation 0) is stale: the joint was removed, or never made here");
  refused([&] { removeJoint(world, never); }, "removeJoint: joint id (slot 2, generation 0) is stale");
}

INSTANTIATE_TEST_SUITE_P(Dt, JointChanges, testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const testing::TestParamInfo<double>& info) { return "dt_1_" + std::to_string(std::lround(1.0 / info.param)); });

}  // namespace
}  // namespace rbsim::test::joint_changes
