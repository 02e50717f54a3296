// The World's side of joints (engine/world/joints.cpp): refused under PGS, no collision between
// jointed bodies unless asked, one sleep island, and joints following destroyed bodies.
#include <gtest/gtest.h>

#include <stdexcept>

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
    joint.bodyA = 1;
    joint.bodyB = 0;
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
  joint.bodyA = 1;
  joint.bodyB = 0;
  joint.anchor = Vec3(0.0, -0.25, 0.0);
  world.addJoint(joint);
  for (int i = 0; i < 120; ++i) world.step();
  ASSERT_FALSE(world.bodies()[0].awake());
  ASSERT_FALSE(world.bodies()[1].awake());
  world.body(std::size_t{1}).setVelocity(Vec3(1.0, 0.0, 0.0));
  world.step();
  EXPECT_TRUE(world.bodies()[0].awake());
  EXPECT_GT(world.bodies()[0].velocity().norm(), 0.0);  // pulled along by the joint
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
  world.addBody(weightDef);
  JointDef joint;
  joint.bodyA = 2;
  joint.bodyB = 1;
  joint.anchor = Vec3(0.0, 1.8, 0.0);
  world.addJoint(joint);
  world.destroyBody(first);  // the weight moves into index 0
  ASSERT_EQ(world.joints().size(), 1u);
  EXPECT_EQ(world.joints()[0].def.bodyA, 0u);
  EXPECT_EQ(world.joints()[0].def.bodyB, 1u);
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_NEAR(world.bodies()[0].position().y(), 1.5, 1e-3);  // still hanging
  world.destroyBody(hook);
  EXPECT_TRUE(world.joints().empty());
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_LT(world.bodies()[0].position().y(), 1.0);  // falling free
}

}  // namespace
}  // namespace rbsim::test
