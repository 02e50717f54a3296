// The "joints" array of a scene (engine/src/scene/joint_parser.cpp): read into JointDef, overridden
// by name with --set, built into the World, and refused with the field named.
#include <gtest/gtest.h>

#include <string>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"

namespace rbsim {
namespace {

const char* kDoor = R"({"world": {"dt": 0.01, "duration": 0.1},
 "bodies": [{"name": "frame", "shape": {"type": "box", "extents": [0.2, 0.2, 0.2]}, "mass": 1, "static": true},
            {"name": "door", "shape": {"type": "box", "extents": [1, 2, 0.05]}, "mass": 20, "position": [0.6, 0, 0]}],
 "joints": [{"name": "hinge", "type": "hinge", "body_a": "door", "body_b": "frame", "anchor": [0.1, 0, 0],
             "axis": [0, 2, 0], "motor": {"speed": 1, "max_torque": 5}, "limits": [-1, 1]},
            {"type": "ball", "body_a": "door", "anchor": [1, 0, 0], "collide_connected": true}]})";

TEST(JointParser, ReadsEveryKey) {
  const Scene scene = parseSceneText(kDoor, "door.json", "");
  ASSERT_EQ(scene.joints.size(), 2u);
  const JointDef& hinge = scene.joints[0];
  EXPECT_EQ(hinge.type, JointDef::Type::Hinge);
  EXPECT_EQ(hinge.bodyA, sceneBodyId(1));
  EXPECT_EQ(hinge.bodyB, sceneBodyId(0));
  EXPECT_TRUE(hinge.anchor.isApprox(Vec3(0.1, 0.0, 0.0)));
  EXPECT_TRUE(hinge.axis.isApprox(Vec3::UnitY()));  // a direction: its length does not matter
  EXPECT_TRUE(hinge.motor);
  EXPECT_EQ(hinge.motorSpeed, 1.0);
  EXPECT_EQ(hinge.maxMotorTorque, 5.0);
  EXPECT_TRUE(hinge.limits);
  EXPECT_EQ(hinge.lowerAngle, -1.0);
  EXPECT_EQ(hinge.upperAngle, 1.0);
  EXPECT_FALSE(hinge.collideConnected);
  const JointDef& ball = scene.joints[1];
  EXPECT_EQ(ball.type, JointDef::Type::Ball);
  EXPECT_EQ(ball.bodyB, kWorldAnchor);
  EXPECT_TRUE(ball.collideConnected);
  EXPECT_EQ(buildWorld(scene).joints().size(), 2u);
}

TEST(JointParser, SetChangesAJointByName) {
  const Scene scene = parseSceneText(kDoor, "door.json", "", {"joints.hinge.motor.speed=-2", "joints[1].anchor=[2,0,0]"});
  EXPECT_EQ(scene.joints[0].motorSpeed, -2.0);
  EXPECT_TRUE(scene.joints[1].anchor.isApprox(Vec3(2.0, 0.0, 0.0)));
}

TEST(JointParser, BadValuesNameTheField) {
  const auto fieldOf = [](const std::string& assignment) {
    try {
      parseSceneText(kDoor, "door.json", "", {assignment});
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(fieldOf("joints.hinge.type=slider"), "joints[0].type");
  EXPECT_EQ(fieldOf("joints.hinge.body_b=nobody"), "joints[0].body_b");
  EXPECT_EQ(fieldOf("joints.hinge.limits=[0.5,0.2]"), "joints[0].limits");
  EXPECT_EQ(fieldOf("joints.hinge.motor.max_torque=-1"), "joints[0].motor.max_torque");
  EXPECT_EQ(fieldOf("joints.hinge.motor.max_torque=1e300"), "joints[0].motor.max_torque");  // past kMaxMotorTorque
  EXPECT_EQ(fieldOf("joints.hinge.motor.max_torque=1e12"), "accepted");
  EXPECT_EQ(fieldOf("joints.hinge.motor.speed=-2e5"), "joints[0].motor.speed");  // past kMaxMotorSpeed
  EXPECT_EQ(fieldOf("joints.hinge.motor.speed=-1e5"), "accepted");
  EXPECT_EQ(fieldOf("joints[1].axis=[0,1,0]"), "accepted");  // the axis of a ball's cone and twist
  EXPECT_EQ(fieldOf("joints[1].motor={\"speed\":1,\"max_torque\":1}"), "joints[1].motor");  // a ball joint has no motor
  EXPECT_EQ(fieldOf("joints[1].cone=0.5"), "joints[1].axis");  // a cone needs its axis
  EXPECT_EQ(fieldOf("joints.hinge.cone=0.5"), "joints[0].cone");  // a hinge has no cone
  EXPECT_EQ(fieldOf("joints.hinge.friction=-1"), "joints[0].friction");
  EXPECT_EQ(fieldOf("joints.hinge.spring={\"hertz\":0}"), "joints[0].spring.hertz");
  EXPECT_EQ(fieldOf("joints.hinge.spring={\"damping_ratio\":1}"), "joints[0].spring.hertz");
  EXPECT_EQ(fieldOf("joints.hinge.spring={\"hertz\":2,\"damping_ratio\":-1}"), "joints[0].spring.damping_ratio");
  EXPECT_EQ(fieldOf("joints.hinge.linear_hertz=5"), "joints[0].linear_hertz");  // a weld's key
  EXPECT_EQ(fieldOf("world.solver=pgs"), "joints[0].type");
}

// The joint family of issue 40: a ball with cone, twist, spring and friction; a slider with motor,
// limits in metres, spring and friction; a soft weld. Each type refuses the others' keys.
const char* kFamily = R"({"world": {"dt": 0.01, "duration": 0.1},
 "bodies": [{"name": "arm", "shape": {"type": "capsule", "radius": 0.05, "length": 0.3}, "mass": 1},
            {"name": "cart", "shape": {"type": "box", "extents": [0.4, 0.2, 0.2]}, "mass": 2, "position": [2, 0, 0]},
            {"name": "beam", "shape": {"type": "box", "extents": [1, 0.1, 0.1]}, "mass": 1, "position": [4, 0, 0]}],
 "joints": [{"name": "shoulder", "type": "ball", "body_a": "arm", "anchor": [0, 0.2, 0], "axis": [0, -1, 0],
             "cone": 0.7, "twist": [-0.3, 0.4], "spring": {"hertz": 2, "damping_ratio": 0.5}, "friction": 0.2},
            {"name": "rail", "type": "prismatic", "body_a": "cart", "anchor": [2, 0, 0], "axis": [1, 0, 0],
             "motor": {"speed": 0.5, "max_force": 10}, "limits": [-0.5, 1.5], "spring": {"hertz": 1}, "friction": 3},
            {"name": "mount", "type": "weld", "body_a": "beam", "anchor": [3.5, 0, 0], "linear_hertz": 5,
             "linear_damping_ratio": 0.7, "angular_hertz": 4, "angular_damping_ratio": 1}]})";

TEST(JointParser, ReadsTheJointFamilysKeys) {
  const Scene scene = parseSceneText(kFamily, "family.json", "");
  ASSERT_EQ(scene.joints.size(), 3u);
  const JointDef& shoulder = scene.joints[0];
  EXPECT_EQ(shoulder.type, JointDef::Type::Ball);
  EXPECT_TRUE(shoulder.axis.isApprox(-Vec3::UnitY()));
  EXPECT_TRUE(shoulder.coneLimit);
  EXPECT_EQ(shoulder.coneAngle, 0.7);
  EXPECT_TRUE(shoulder.limits);
  EXPECT_EQ(shoulder.lowerAngle, -0.3);
  EXPECT_EQ(shoulder.upperAngle, 0.4);
  EXPECT_TRUE(shoulder.spring);
  EXPECT_EQ(shoulder.springHertz, 2.0);
  EXPECT_EQ(shoulder.springDampingRatio, 0.5);
  EXPECT_EQ(shoulder.friction, 0.2);
  const JointDef& rail = scene.joints[1];
  EXPECT_EQ(rail.type, JointDef::Type::Prismatic);
  EXPECT_TRUE(rail.motor);
  EXPECT_EQ(rail.motorSpeed, 0.5);
  EXPECT_EQ(rail.maxMotorForce, 10.0);
  EXPECT_TRUE(rail.limits);
  EXPECT_EQ(rail.lowerTranslation, -0.5);
  EXPECT_EQ(rail.upperTranslation, 1.5);
  EXPECT_EQ(rail.springHertz, 1.0);
  EXPECT_EQ(rail.springDampingRatio, 0.0);
  EXPECT_EQ(rail.friction, 3.0);
  const JointDef& mount = scene.joints[2];
  EXPECT_EQ(mount.type, JointDef::Type::Weld);
  EXPECT_EQ(mount.linearHertz, 5.0);
  EXPECT_EQ(mount.linearDampingRatio, 0.7);
  EXPECT_EQ(mount.angularHertz, 4.0);
  EXPECT_EQ(mount.angularDampingRatio, 1.0);
  EXPECT_EQ(buildWorld(scene).joints().size(), 3u);
}

TEST(JointParser, TheJointFamilysBadValuesNameTheField) {
  const auto fieldOf = [](const std::string& assignment) {
    try {
      parseSceneText(kFamily, "family.json", "", {assignment});
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(fieldOf("joints.shoulder.cone=4"), "joints[0].cone");  // past pi
  EXPECT_EQ(fieldOf("joints.shoulder.twist=[0.4,-0.3]"), "joints[0].twist");
  EXPECT_EQ(fieldOf("joints.shoulder.limits=[0,1]"), "joints[0].limits");  // a ball's range is its twist
  EXPECT_EQ(fieldOf("joints.rail.motor.max_torque=1"), "joints[1].motor.max_torque");  // a slider's is max_force
  EXPECT_EQ(fieldOf("joints.rail.motor.max_force=-1"), "joints[1].motor.max_force");
  EXPECT_EQ(fieldOf("joints.rail.limits=[2,1]"), "joints[1].limits");
  EXPECT_EQ(fieldOf("joints.rail.limits=[-5,5]"), "accepted");  // metres, not bound to pi
  EXPECT_EQ(fieldOf("joints.rail.axis=[0,0,0]"), "joints[1].axis");
  EXPECT_EQ(fieldOf("joints.mount.friction=1"), "joints[2].friction");  // a weld has none
  EXPECT_EQ(fieldOf("joints.mount.angular_hertz=-4"), "joints[2].angular_hertz");
  EXPECT_EQ(fieldOf("joints.mount.axis=[1,0,0]"), "joints[2].axis");
}

// More joints than kMaxJoints are refused by their count, before any is read.
TEST(JointParser, MoreJointsThanTheLimitAreRefusedByTheirCount) {
  nlohmann::json doc = {{"bodies", {{{"name", "a"}, {"shape", {{"type", "sphere"}, {"radius", 0.1}}}, {"mass", 1.0}}}}};
  doc["joints"] = nlohmann::json::array();
  for (int i = 0; i < 1'000'001; ++i) doc["joints"].push_back(nullptr);
  try {
    parseScene(doc, "many.json", "");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("joints: 1000001 joints; the limit is 1000000"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rbsim
