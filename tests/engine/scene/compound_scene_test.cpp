// The scene keys of issue 40 (scene/compound_parser.h): a body's "shapes", "filter" and
// "motion", read into the engine's structures, and each bad value refused naming its path.
#include <functional>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "test_util.h"

namespace rbsim {
namespace {

using nlohmann::json;
using test::allNear;

json table() {
  json shapes = json::array({{{"type", "box"}, {"extents", {1.2, 0.06, 0.8}}, {"position", {0, 0.73, 0}}, {"friction_static", 0.9},
                              {"friction_kinetic", 0.8}}});
  for (const double x : {-0.55, 0.55}) {
    for (const double z : {-0.35, 0.35}) {
      shapes.push_back({{"type", "box"}, {"extents", {0.06, 0.7, 0.06}}, {"position", {x, 0.35, z}}, {"filter", {{"category", 2}}}});
    }
  }
  return {{"name", "table"}, {"shapes", shapes}, {"mass", 12.0}, {"position", {0, 0.5, 0}}};
}

json sceneOf(const json& body) {
  return {{"world", {{"dt", 0.01}}}, {"bodies", json::array({body})}};
}

std::string errorField(const json& doc) {
  try {
    parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  } catch (const InputError& e) {
    return e.field() + ": " + e.problem();
  }
  return "no error";
}

TEST(CompoundScene, ShapesMakeACompoundBody) {
  const Scene scene = parseScene(sceneOf(table()), "test.json", RBSIM_TEST_DATA_DIR);
  const BodyDef& def = scene.bodies.at(0);
  ASSERT_EQ(def.children.size(), 5u);
  EXPECT_NEAR(def.mass, 12.0, 1e-12);
  EXPECT_EQ(def.children[0].material.staticFriction, 0.9);
  EXPECT_EQ(def.children[1].filter.category, 2u);
  EXPECT_EQ(def.children[1].filter.mask, ~std::uint64_t{0});
  // The position is the centre of mass's; the children sit about it.
  EXPECT_TRUE(allNear(def.position, Vec3(0, 0.5, 0), 0.0));
  EXPECT_TRUE(allNear(def.children[0].position + def.fileFrame.centre, Vec3(0, 0.73, 0), 1e-12));
  const World w = buildWorld(scene);
  EXPECT_TRUE(w.bodies()[0].isCompound());
}

TEST(CompoundScene, FilterAndMotionAreRead) {
  json ball = {{"name", "ball"}, {"shape", {{"type", "sphere"}, {"radius", 0.5}}}, {"mass", 1}, {"filter", {{"category", 4}, {"mask", 5}, {"group", -3}}}};
  json door = {{"name", "door"}, {"shape", {{"type", "box"}, {"extents", {1, 2, 0.1}}}}, {"kinematic", true}, {"mass", 1},
               {"position", {0.5, 1, 0}}, {"motion", {{"pivot", {0, 1, 0}}, {"angular_velocity", {0, 1, 0}}}}};
  json lift = {{"name", "lift"}, {"shape", {{"type", "box"}, {"extents", {1, 0.1, 1}}}}, {"kinematic", true}, {"mass", 1},
               {"motion", {{"loop", true}, {"keyframes", {{{"time", 0}, {"position", {0, 0, 0}}},
                                                         {{"time", 2}, {"position", {0, 3, 0}}, {"orientation", {{"axis_angle_deg", {0, 1, 0, 90}}}}}}}}}};
  json doc = {{"world", {{"dt", 0.01}}}, {"bodies", {ball, door, lift}}};
  const Scene scene = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  EXPECT_EQ(scene.bodies[0].filter.category, 4u);
  EXPECT_EQ(scene.bodies[0].filter.mask, 5u);
  EXPECT_EQ(scene.bodies[0].filter.group, -3);
  ASSERT_EQ(scene.motions.size(), 2u);
  EXPECT_EQ(scene.motions[0].kind, KinematicMotion::Kind::Pivot);
  EXPECT_TRUE(allNear(scene.motions[0].pivot, Vec3(0, 1, 0), 0.0));
  EXPECT_EQ(scene.motions[1].kind, KinematicMotion::Kind::Keyframes);
  EXPECT_TRUE(scene.motions[1].loop);
  ASSERT_EQ(scene.motions[1].keys.size(), 2u);
  EXPECT_NEAR(scene.motions[1].keys[1].orientation.angularDistance(Quat::Identity()), kPi / 2, 1e-12);
  World w = buildWorld(scene);
  EXPECT_EQ(kinematicMotions(w).size(), 2u);
}

TEST(CompoundScene, BadValuesNameTheirPath) {
  const auto withTable = [](const std::function<void(json&)>& change) {
    json body = table();
    change(body);
    return errorField(sceneOf(body));
  };
  EXPECT_EQ(withTable([](json& b) { b["shape"] = {{"type", "sphere"}}; }).rfind("bodies[0].shapes:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"] = json::array(); }).rfind("bodies[0].shapes:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"][1]["type"] = "torus"; }).rfind("bodies[0].shapes[1].type:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"][2]["density"] = -1; }).rfind("bodies[0].shapes[2].density:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"][2]["filter"] = {{"category", -1}}; }).rfind("bodies[0].shapes[2].filter.category:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"][2]["filter"] = {{"group", 3e9}}; }).rfind("bodies[0].shapes[2].filter.group:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"][2]["filter"] = {{"groop", 3}}; }).rfind("bodies[0].shapes[2].filter.groop:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["friction_static"] = 0.2; }).rfind("bodies[0].friction_static:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["filter"] = {{"category", 2}}; }).rfind("bodies[0].filter:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["density"] = 5; }).rfind("bodies[0].density:", 0), 0u);
  EXPECT_EQ(withTable([](json& b) { b["shapes"] = json::array({table()["shapes"][0]}); b["shapes"][0]["extents"] = {1, 0, 1}; })
                .rfind("bodies[0].shapes[0].extents:", 0),
            0u);
  EXPECT_EQ(withTable([](json& b) { b["motion"] = {{"pivot", {0, 0, 0}}}; }).rfind("bodies[0].motion:", 0), 0u);  // not kinematic
  const auto withLift = [](const json& motion) {
    json body = {{"name", "lift"}, {"shape", {{"type", "box"}, {"extents", {1, 0.1, 1}}}}, {"kinematic", true}, {"mass", 1}, {"motion", motion}};
    return errorField(sceneOf(body));
  };
  EXPECT_EQ(withLift({{"keyframes", {{{"time", 1}}, {{"time", 1}}}}}).rfind("bodies[0].motion.keyframes:", 0), 0u);
  EXPECT_EQ(withLift({{"keyframes", {{{"time", -1}}}}}).rfind("bodies[0].motion.keyframes[0].time:", 0), 0u);
  EXPECT_EQ(withLift({{"keyframes", {{{"time", 1}}}}, {"pivot", {0, 0, 0}}}).rfind("bodies[0].motion.keyframes:", 0), 0u);
  EXPECT_EQ(withLift({{"pivot", {0, 0, 0}}, {"loop", true}}).rfind("bodies[0].motion.loop:", 0), 0u);
  EXPECT_EQ(withLift({{"angular_velocity", {0, "a", 0}}}).rfind("bodies[0].motion.angular_velocity:", 0), 0u);
}

TEST(CompoundScene, RagdollsAreAddedWithTheirJoints) {
  json doc = {{"world", {{"dt", 1.0 / 60.0}}},
              {"planes", {{{"normal", {0, 1, 0}}}}},
              {"ragdolls", {{{"name", "ann"}, {"position", {0, 2, 0}}, {"scale", 0.5}},
                            {{"name", "bob"}, {"position", {2, 2, 0}}, {"joint_hertz", 0}}}}};
  const Scene scene = parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  ASSERT_EQ(scene.ragdolls.size(), 2u);
  EXPECT_EQ(scene.ragdolls[0].scale, 0.5);
  EXPECT_EQ(scene.ragdolls[1].jointHertz, 0.0);
  const World w = buildWorld(scene);
  EXPECT_EQ(w.bodies().size(), 2 * kBoneCount);
  EXPECT_EQ(w.joints().size(), 2 * (kBoneCount - 1));
  EXPECT_EQ(w.bodies()[0].name(), "ann_pelvis");

  const auto field = [&](const std::function<void(json&)>& change) {
    json bad = doc;
    change(bad);
    return errorField(bad);
  };
  EXPECT_EQ(field([](json& d) { d["ragdolls"][0]["scale"] = 100; }).rfind("ragdolls[0].scale:", 0), 0u);
  EXPECT_EQ(field([](json& d) { d["ragdolls"][1]["name"] = "ann"; }).rfind("ragdolls[1].name:", 0), 0u);
  EXPECT_EQ(field([](json& d) { d["ragdolls"][0]["joint_friction"] = -1; }).rfind("ragdolls[0].joint_friction:", 0), 0u);
  EXPECT_EQ(field([](json& d) { d["world"]["solver"] = "pgs"; }).rfind("ragdolls:", 0), 0u);
  EXPECT_EQ(field([](json& d) { d["ragdolls"][0]["sacle"] = 1; }).rfind("ragdolls[0].sacle:", 0), 0u);
}

}  // namespace
}  // namespace rbsim
