// Joint and spring ids of a generation (world/item_ids.h, body/id_table.h; issue 58, as Box2D
// v3's b2JointId): an id names its joint or spring while others come and go; a removed one's id,
// by hand or with its body, is refused with the World unchanged, even once its slot is reused; a
// World read back from a snapshot keeps the ids. At dt = 1/60 and 1/240 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/world/joint_changes.h"
#include "rbsim/world/joint_reading.h"
#include "rbsim/world/spring.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_snapshot.h"
#include "test_util.h"
#include "refusal.h"

namespace rbsim::test::joint_spring_ids {
namespace {

constexpr double kSpeed = 3.0;         // a motor's target [rad/s]
constexpr double kMaxTorque = 100.0;   // [N m]: a 0.04 kg m^2 wheel reaches kSpeed within a step
constexpr double kStiffness = 20.0;    // a spring's k [N/m]
constexpr int kWheels = 3;

class JointSpringIds : public testing::TestWithParam<double> {
 protected:
  double dt() const { return GetParam(); }
  // Three wheels "a", "b", "c" 3 m apart on x, no gravity, never asleep.
  World wheels() const {
    Settings s;
    s.timeStep = dt();
    s.gravity = Vec3::Zero();
    s.allowSleep = false;
    World world(s);
    for (int k = 0; k < kWheels; ++k) {
      BodyDef wheel = boxDef(Vec3(0.5, 0.5, 0.1), 1.0, std::string(1, static_cast<char>('a' + k)));
      wheel.position = Vec3(3.0 * k, 0.0, 0.0);
      world.addBody(wheel);
    }
    return world;
  }
  // A hinge about z from wheel k to the world at its centre, motor off.
  static JointId hinge(World& world, int k) {
    JointDef def;
    def.type = JointDef::Type::Hinge;
    def.bodyA = world.idAt(static_cast<std::size_t>(k));
    def.anchor = world.bodies()[static_cast<std::size_t>(k)].position();
    def.name = world.bodies()[static_cast<std::size_t>(k)].name();
    return world.addJoint(def);
  }
  // A spring on wheel k's centre, its anchor there (no force until it moves).
  static SpringId spring(World& world, int k) {
    Spring s;
    s.body = world.idAt(static_cast<std::size_t>(k));
    s.anchor = world.bodies()[static_cast<std::size_t>(k)].position();
    s.stiffness = kStiffness;
    return addSpring(world, s);
  }
  void run(World& world, double seconds) const {
    for (int i = 0; i < static_cast<int>(std::lround(seconds / dt())); ++i) world.step();
  }
};

// Of three hinges, the first removed: the third's id still names wheel c's hinge (now at index 1,
// where b's was), and the motor set through it turns c at kSpeed while b, now at index 0, stays
// still.
TEST_P(JointSpringIds, JointIdNamesItsJointAfterAnEarlierOneIsRemoved) {
  World world = wheels();
  const JointId a = hinge(world, 0), b = hinge(world, 1), c = hinge(world, 2);
  removeJoint(world, a);
  ASSERT_EQ(world.joints().size(), 2u);
  EXPECT_EQ(indexOf(world, b), 0u);
  EXPECT_EQ(indexOf(world, c), 1u);
  EXPECT_EQ(jointIdAt(world, 1), c);
  setJointMotor(world, c, true, kSpeed, kMaxTorque);
  EXPECT_EQ(world.joints()[indexOf(world, c)].def.name, "c");
  EXPECT_TRUE(world.joints()[indexOf(world, c)].def.motor);
  EXPECT_FALSE(world.joints()[indexOf(world, b)].def.motor);
  run(world, 0.5);
  EXPECT_NEAR(readJoint(world, indexOf(world, c)).speed, kSpeed, 1e-6);
  EXPECT_EQ(readJoint(world, indexOf(world, b)).speed, 0.0);
  EXPECT_EQ(world.body(world.idAt(1)).angularVelocity().norm(), 0.0);  // wheel b never turned
}

// A removed joint's id, and the id of a joint removed with its body, are refused by every call
// naming it, the call and "stale" in the words, and the World's saved bytes do not change.
TEST_P(JointSpringIds, StaleJointIdsAreRefusedAndChangeNothing) {
  World world = wheels();
  const JointId a = hinge(world, 0), b = hinge(world, 1);
  hinge(world, 2);
  removeJoint(world, a);
  world.destroyBody(world.idAt(1));  // takes hinge b with it
  ASSERT_EQ(world.joints().size(), 1u);
  world.step();
  const std::vector<std::uint8_t> before = saveWorldSnapshot(world);
  for (const JointId stale : {a, b}) {
    EXPECT_FALSE(isValid(world, stale));
    expectRefused([&] { setJointMotor(world, stale, true, kSpeed, kMaxTorque); }, "setJointMotor: joint id (slot " +
                  std::to_string(stale.slot) + ", generation " + std::to_string(stale.generation) + ") is stale");
    expectRefused([&] { setJointLimits(world, stale, true, -1.0, 1.0); }, "setJointLimits: joint id");
    expectRefused([&] { removeJoint(world, stale); }, "removeJoint: joint id");
    expectRefused([&] { static_cast<void>(indexOf(world, stale)); }, "is stale");
    EXPECT_EQ(saveWorldSnapshot(world), before);
  }
  expectRefused([&] { static_cast<void>(jointIdAt(world, 1)); }, "jointIdAt: no joint at index 1");
}

// A new joint takes the removed one's slot with the next generation: the old id stays refused
// and the new one works.
TEST_P(JointSpringIds, AReusedJointSlotDoesNotReviveTheOldId) {
  World world = wheels();
  const JointId old = hinge(world, 0);
  removeJoint(world, old);
  const JointId reused = hinge(world, 1);
  EXPECT_EQ(reused.slot, old.slot);
  EXPECT_NE(reused.generation, old.generation);
  EXPECT_FALSE(isValid(world, old));
  const std::vector<std::uint8_t> before = saveWorldSnapshot(world);
  expectRefused([&] { setJointMotor(world, old, true, kSpeed, kMaxTorque); }, "is stale");
  EXPECT_EQ(saveWorldSnapshot(world), before);
  setJointMotor(world, reused, true, kSpeed, kMaxTorque);
  run(world, 0.5);
  EXPECT_NEAR(readJoint(world, indexOf(world, reused)).speed, kSpeed, 1e-6);
  EXPECT_EQ(world.body(world.idAt(0)).angularVelocity().norm(), 0.0);  // wheel a is free, still
}

// Of three springs, the first removed: the third's id still names wheel c's spring, and moving
// its anchor 1 m along +y pulls c, whose velocity after the first step is k d / m dt, while b
// (index 0 now) stays put.
TEST_P(JointSpringIds, SpringIdNamesItsSpringAfterAnEarlierOneIsRemoved) {
  World world = wheels();
  const SpringId a = spring(world, 0), b = spring(world, 1), c = spring(world, 2);
  removeSpring(world, a);
  ASSERT_EQ(springs(world).size(), 2u);
  EXPECT_EQ(indexOf(world, b), 0u);
  EXPECT_EQ(indexOf(world, c), 1u);
  EXPECT_EQ(springIdAt(world, 1), c);
  moveSpringAnchor(world, c, Vec3(6.0, 1.0, 0.0));
  EXPECT_EQ(springs(world)[indexOf(world, c)].body, world.idAt(2));
  EXPECT_EQ(springs(world)[indexOf(world, b)].anchor, Vec3(3.0, 0.0, 0.0));
  world.step();
  EXPECT_NEAR(world.bodies()[2].velocity().y(), kStiffness * 1.0 / 1.0 * dt(), 1e-12);  // k d / m dt
  EXPECT_EQ(world.bodies()[1].velocity().norm(), 0.0);
}

// A removed spring's id, and that of a spring removed with its body, are refused with the World
// unchanged; a new spring in the freed slot does not revive the old id.
TEST_P(JointSpringIds, StaleSpringIdsAreRefusedAndAReusedSlotDoesNotReviveThem) {
  World world = wheels();
  const SpringId a = spring(world, 0), b = spring(world, 1);
  spring(world, 2);
  removeSpring(world, a);
  world.destroyBody(world.idAt(1));  // takes spring b with it
  ASSERT_EQ(springs(world).size(), 1u);
  world.step();
  const std::vector<std::uint8_t> before = saveWorldSnapshot(world);
  for (const SpringId stale : {a, b}) {
    EXPECT_FALSE(isValid(world, stale));
    expectRefused([&] { moveSpringAnchor(world, stale, Vec3(0.0, 5.0, 0.0)); }, "moveSpringAnchor: spring id (slot " +
                  std::to_string(stale.slot) + ", generation " + std::to_string(stale.generation) + ") is stale");
    expectRefused([&] { removeSpring(world, stale); }, "removeSpring: spring id");
    EXPECT_EQ(saveWorldSnapshot(world), before);
  }
  expectRefused([&] { static_cast<void>(springIdAt(world, 1)); }, "springIdAt: no spring at index 1");
  const SpringId reused = spring(world, 0);
  EXPECT_TRUE(reused.slot == a.slot || reused.slot == b.slot);
  EXPECT_FALSE(isValid(world, a));
  EXPECT_FALSE(isValid(world, b));
  EXPECT_TRUE(isValid(world, reused));
  moveSpringAnchor(world, reused, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(springs(world)[indexOf(world, reused)].body, world.idAt(0));
}

// A World read back from a snapshot keeps the id tables: ids taken before the save name the same
// joint and spring there (the motor set through one turns that wheel), and a stale one is still
// refused there.
TEST_P(JointSpringIds, IdsSurviveASnapshot) {
  World world = wheels();
  const JointId ja = hinge(world, 0), jc = hinge(world, 2);
  const SpringId sa = spring(world, 0), sb = spring(world, 1);
  removeJoint(world, ja);
  removeSpring(world, sa);
  world.step();
  const World base = wheels();
  World read = loadWorldSnapshot(saveWorldSnapshot(world), base);
  ASSERT_TRUE(isValid(read, jc));
  EXPECT_EQ(read.joints()[indexOf(read, jc)].def.name, "c");
  EXPECT_FALSE(isValid(read, ja));
  expectRefused([&] { setJointMotor(read, ja, true, kSpeed, kMaxTorque); }, "is stale");
  ASSERT_TRUE(isValid(read, sb));
  EXPECT_EQ(springs(read)[indexOf(read, sb)].body, read.idAt(1));
  expectRefused([&] { removeSpring(read, sa); }, "is stale");
  // A joint added to each takes the same slot and generation: the tables' free lists agree.
  EXPECT_EQ(hinge(read, 1), hinge(world, 1));
  setJointMotor(read, jc, true, kSpeed, kMaxTorque);
  run(read, 0.5);
  EXPECT_NEAR(readJoint(read, indexOf(read, jc)).speed, kSpeed, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, JointSpringIds, testing::Values(1.0 / 60.0, 1.0 / 240.0));

}  // namespace
}  // namespace rbsim::test::joint_spring_ids
