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
  EXPECT_EQ(fieldOf("joints[1].axis=[0,1,0]"), "joints[1].axis");  // a ball joint has no axis
  EXPECT_EQ(fieldOf("world.solver=pgs"), "joints[0].type");
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
