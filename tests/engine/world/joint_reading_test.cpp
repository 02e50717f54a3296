// readJoint (world/joint_reading.h) against statics and closed forms: a body hanging at rest
// feels m g from its joint; a motor holding a level rod gives m g d; a free hinge reads the spin
// it was given and the angle it turned; a limit holds the angle it names. At the time steps users
// pick, 1/60 and 1/240 s.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "rbsim/world/joint_reading.h"
#include "rbsim/world/world.h"
#include "test_util.h"

namespace rbsim::test {
namespace {

constexpr double kG = 9.81;     // [m/s^2]
constexpr double kMass = 2.0;   // [kg]

Settings settings(double dt) {
  Settings s;
  s.timeStep = dt;
  s.gravity = Vec3(0.0, -kG, 0.0);
  s.allowSleep = false;
  return s;
}

// A 1 m rod along x, centre at (0.5, 0, 0), on a joint at the origin held by the world.
World rodOnJoint(double dt, JointDef joint) {
  World world(settings(dt));
  BodyDef rod = boxDef(Vec3(1.0, 0.1, 0.1), kMass, "rod");
  rod.position = Vec3(0.5, 0.0, 0.0);
  world.addBody(rod);
  joint.bodyA = world.idAt(0);
  world.addJoint(joint);
  return world;
}

class JointReadingAt : public ::testing::TestWithParam<double> {};

TEST_P(JointReadingAt, ABodyHangingAtRestFeelsItsWeightFromTheJoint) {
  World world(settings(GetParam()));
  BodyDef bob = boxDef(Vec3(0.2, 0.2, 0.2), kMass, "bob");
  bob.position = Vec3(0.0, -1.0, 0.0);
  world.addBody(bob);
  JointDef joint;
  joint.bodyA = world.idAt(0);
  world.addJoint(joint);
  for (int i = 0; i < 200; ++i) world.step();
  const JointReading r = readJoint(world, 0);
  EXPECT_NEAR(r.force.y(), kMass * kG, 1e-6 * kMass * kG);
  EXPECT_NEAR(r.force.x(), 0.0, 1e-9);
  EXPECT_NEAR(r.force.z(), 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(r.angle) && std::isnan(r.speed));  // a ball joint has no axis
  EXPECT_LT((r.anchorA - r.anchorB).norm(), 1e-3);
  EXPECT_LT((r.anchorB - Vec3::Zero()).norm(), 1e-15);
}

TEST_P(JointReadingAt, AMotorHoldingALevelRodGivesItsMomentAndItsWeight) {
  JointDef hinge;
  hinge.type = JointDef::Type::Hinge;
  hinge.axis = Vec3::UnitZ();
  hinge.motor = true;
  hinge.motorSpeed = 0.0;
  hinge.maxMotorTorque = 1e3;  // [N m], far above the m g d = 9.81 N m it holds
  World world = rodOnJoint(GetParam(), hinge);
  for (int i = 0; i < 200; ++i) world.step();
  const JointReading r = readJoint(world, 0);
  // The rod's centre is 0.5 m out (a little less as the motor gives way by its softness).
  const double arm = world.bodies()[0].position().x();
  EXPECT_NEAR(arm, 0.5, 1e-3);
  EXPECT_NEAR(r.torque.z(), kMass * kG * arm, 1e-6 * kMass * kG);
  EXPECT_NEAR(r.force.y(), kMass * kG, 1e-6 * kMass * kG);
  EXPECT_NEAR(r.speed, 0.0, 1e-9);
  EXPECT_LT(std::abs(r.angle), 2e-3);  // the sag
}

TEST_P(JointReadingAt, AFreeHingeReadsTheSpinItWasGivenAndTheAngleItTurned) {
  JointDef hinge;
  hinge.type = JointDef::Type::Hinge;
  hinge.axis = Vec3::UnitZ();
  World world = rodOnJoint(GetParam(), hinge);
  Settings s = world.settings();
  s.gravity = Vec3::Zero();
  world.setSettings(s);
  const double omega = 1.5;  // [rad/s] about the hinge at the origin: the centre moves at omega * 0.5
  RigidBody& rod = world.body(world.idAt(0));
  rod.setVelocity(Vec3(0.0, omega * 0.5, 0.0));
  rod.setAngularVelocity(Vec3(0.0, 0.0, omega));
  const int steps = static_cast<int>(std::lround(1.0 / GetParam()));  // one second
  for (int i = 0; i < steps; ++i) world.step();
  const JointReading r = readJoint(world, 0);
  // The soft joint's damping takes a little of the spin: 9e-6 rad/s in the second at 1/60 s, 3e-6
  // at 1/240 (measured); the reading is what the bodies do.
  EXPECT_NEAR(r.speed, omega, 2e-5);
  EXPECT_NEAR(r.angle, omega * 1.0, 4e-5);
  EXPECT_LT(r.force.norm(), kMass * omega * omega * 0.5 * 1.001);  // the centripetal pull m w^2 r
  EXPECT_GT(r.force.norm(), kMass * omega * omega * 0.5 * 0.999);
}

TEST_P(JointReadingAt, ALimitHoldsTheAngleItNames) {
  JointDef hinge;
  hinge.type = JointDef::Type::Hinge;
  hinge.axis = Vec3::UnitZ();
  hinge.limits = true;
  hinge.lowerAngle = -0.5;  // [rad]: gravity swings the rod down, to this stop
  hinge.upperAngle = 0.5;
  World world = rodOnJoint(GetParam(), hinge);
  for (int i = 0; i < 600; ++i) world.step();
  const JointReading r = readJoint(world, 0);
  EXPECT_NEAR(r.angle, -0.5, 5e-3);
  EXPECT_NEAR(r.speed, 0.0, 1e-6);
  // The stop holds the rod's moment about the hinge: m g times the centre's horizontal arm.
  EXPECT_NEAR(r.torque.z(), kMass * kG * 0.5 * std::cos(r.angle), 1e-3 * kMass * kG);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, JointReadingAt, ::testing::Values(1.0 / 60.0, 1.0 / 240.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return "Dt1_" + std::to_string(std::lround(1.0 / info.param));
                         });

TEST(JointReading, ABadIndexIsRefused) {
  World world(settings(1.0 / 60.0));
  EXPECT_THROW(readJoint(world, 0), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim::test
