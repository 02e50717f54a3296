// The World's side of joints (engine/src/world/joints.cpp): refused under PGS, no collision between
// jointed bodies unless asked, one sleep island, and joints following destroyed bodies.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "test_util.h"
#include "rbsim/world/world.h"

namespace rbsim::test {
namespace {

Settings still() {
  Settings s;
  s.timeStep = 1.0 / 60.0;
  s.gravity = Vec3(0.0, -9.81, 0.0);
  s.allowSleep = false;
  return s;
}

TEST(WorldJoints, PgsRefusesJoints) {
  Settings s = still();
  s.solver = Settings::ContactSolverMethod::Pgs;
  World world(s);
  world.addBody(boxDef(Vec3(0.1, 1.0, 0.1), 1.0, "rod"));
  JointDef joint;
  EXPECT_THROW(world.addJoint(joint), std::invalid_argument);
}

// Two overlapping boxes joined by a ball joint: no contact between them unless collideConnected.
TEST(WorldJoints, JointedBodiesDoNotCollideUnlessAsked) {
  for (const bool collide : {false, true}) {
    World world(still());
    BodyDef a = boxDef(Vec3(0.5, 0.5, 0.5), 1.0, "a");
    BodyDef b = boxDef(Vec3(0.5, 0.5, 0.5), 1.0, "b");
    b.position = Vec3(0.3, 0.0, 0.0);
    world.addBody(a);
    world.addBody(b);
    JointDef joint;
    joint.bodyA = world.idAt(1);
    joint.bodyB = world.idAt(0);
    joint.anchor = Vec3(0.15, 0.0, 0.0);
    joint.collideConnected = collide;
    world.addJoint(joint);
    world.step();
    EXPECT_EQ(world.contacts().empty(), !collide);
  }
}

// A body hung from a sleeping one: both sleep as one island, and moving one wakes the other.
TEST(WorldJoints, JointedBodiesSleepAndWakeTogether) {
  Settings s = still();
  s.allowSleep = true;
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef a = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "a");
  BodyDef b = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "b");
  b.position = Vec3(0.0, -0.5, 0.0);
  world.addBody(a);
  world.addBody(b);
  JointDef joint;
  joint.bodyA = world.idAt(1);
  joint.bodyB = world.idAt(0);
  joint.anchor = Vec3(0.0, -0.25, 0.0);
  world.addJoint(joint);
  for (int i = 0; i < 120; ++i) world.step();
  ASSERT_FALSE(world.bodies()[0].awake());
  ASSERT_FALSE(world.bodies()[1].awake());
  world.body(world.idAt(1)).setVelocity(Vec3(1.0, 0.0, 0.0));
  world.step();
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_GT(world.bodies()[0].velocity().norm(), 0.0);  // pulled along by the joint
}

// A motor between two free bodies turns them against each other: no external torque, so the
// pair's angular momentum stays zero while each spins up (the reaction acts on the base).
TEST(WorldJoints, MotorBetweenTwoBodiesKeepsTheirAngularMomentum) {
  Settings s = still();
  s.gravity = Vec3::Zero();
  World world(s);
  BodyDef rotor = boxDef(Vec3(0.6, 0.6, 0.1), 1.0, "rotor");
  BodyDef stator = boxDef(Vec3(1.0, 0.4, 0.3), 3.0, "stator");
  rotor.position = Vec3(0.0, 0.0, 0.3);
  world.addBody(rotor);
  world.addBody(stator);
  JointDef motor;
  motor.type = JointDef::Type::Hinge;
  motor.bodyA = world.idAt(0);
  motor.bodyB = world.idAt(1);
  motor.anchor = Vec3(0.0, 0.0, 0.2);
  motor.axis = Vec3(0.0, 0.0, 1.0);
  motor.motor = true;
  motor.motorSpeed = 5.0;
  motor.maxMotorTorque = 0.5;
  world.addJoint(motor);
  for (int i = 0; i < 240; ++i) world.step();
  Vec3 total = Vec3::Zero();
  for (const RigidBody& b : world.bodies()) total += b.position().cross(b.state().linearMomentum) + b.state().angularMomentum;
  EXPECT_LT(total.norm(), 1e-9) << "kg m^2/s";
  const double relative = world.bodies()[0].angularVelocity().z() - world.bodies()[1].angularVelocity().z();
  EXPECT_NEAR(relative, 5.0, 1e-6);  // reached: 0.5 N m spins both up within 4 s
  EXPECT_LT(world.bodies()[1].angularVelocity().z(), 0.0);
}

// A chain of ten jointed links dropped onto the ground: contacts and joints in one solve. It comes
// to rest on the plane with its joints closed and its energy gone.
TEST(WorldJoints, ChainSettlesOnTheGroundWithItsJointsHeld) {
  Settings s = still();
  World world(s);
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  for (int i = 0; i < 10; ++i) {
    BodyDef link = boxDef(Vec3(0.3, 0.05, 0.05), 0.5, "link" + std::to_string(i));
    link.position = Vec3(0.3 * i + 0.15, 1.0, 0.0);
    world.addBody(link);
    if (i == 0) continue;
    JointDef joint;
    joint.bodyA = world.idAt(static_cast<std::size_t>(i));
    joint.bodyB = world.idAt(static_cast<std::size_t>(i - 1));
    joint.anchor = Vec3(0.3 * i, 1.0, 0.0);
    world.addJoint(joint);
  }
  for (int i = 0; i < 300; ++i) world.step();  // 5 s
  double worst = 0.0, energy = 0.0;
  for (const Joint& j : world.joints()) {
    const Vec3 onA = world.bodies()[world.indexOf(j.def.bodyA)].bodyToWorld(j.localAnchorMoving);
    const Vec3 onB = world.bodies()[world.indexOf(j.def.bodyB)].bodyToWorld(j.localAnchorBase);
    worst = std::max(worst, (onA - onB).norm());
  }
  for (const RigidBody& b : world.bodies()) {
    energy += b.kineticEnergy();
    EXPECT_NEAR(b.position().y(), 0.025, 2e-3) << b.name();
  }
  EXPECT_LT(worst, 1e-3) << "m";
  EXPECT_LT(energy, 1e-4) << "J";
}

// Destroying a body takes its joints with it; the body moved into its index keeps its joints.
TEST(WorldJoints, JointsFollowDestroyedAndMovedBodies) {
  World world(still());
  const BodyId first = world.addBody(boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "first"));
  BodyDef hookDef = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "hook");
  hookDef.isStatic = true;
  hookDef.position = Vec3(0.0, 2.0, 0.0);
  const BodyId hook = world.addBody(hookDef);
  BodyDef weightDef = boxDef(Vec3(0.2, 0.2, 0.2), 1.0, "weight");
  weightDef.position = Vec3(0.0, 1.5, 0.0);
  const BodyId weight = world.addBody(weightDef);
  JointDef joint;
  joint.bodyA = weight;
  joint.bodyB = hook;
  joint.anchor = Vec3(0.0, 1.8, 0.0);
  joint.name = "rope";
  world.addJoint(joint);
  world.destroyBody(first);  // the weight moves into index 0
  ASSERT_EQ(world.joints().size(), 1u);
  EXPECT_EQ(world.joints()[0].def.name, "rope");  // a joint kept in its place keeps everything (issue 57)
  EXPECT_EQ(world.joints()[0].def.bodyA, weight);  // the ids stay
  EXPECT_EQ(world.joints()[0].def.bodyB, hook);
  EXPECT_EQ(world.indexOf(weight), 0u);  // moved: the solver resolves the ids to the new indices
  EXPECT_EQ(world.indexOf(hook), 1u);
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_NEAR(world.bodies()[0].position().y(), 1.5, 1e-3);  // still hanging
  world.destroyBody(hook);
  EXPECT_TRUE(world.joints().empty());
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_LT(world.bodies()[0].position().y(), 1.0);  // falling free
}

}  // namespace
}  // namespace rbsim::test
