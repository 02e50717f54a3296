// The body key "collide_as": "triangles" (issue 40, scene/mesh_ground_parser.h): a static mesh
// becomes a mesh ground, without it a mesh body is what it was, and each misuse names its field.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "test_util.h"

namespace rbsim {
namespace {

using nlohmann::json;

// A closed non-convex mesh (a groundPrism over a concave outline): a grid by default.
json groundPrism() {
  return {{"name", "ground"}, {"shape", {{"type", "mesh"}, {"file", "concave_prism.obj"}}}, {"static", true}, {"mass", 1.0}};
}

json groundSceneOf(const json& body) { return {{"world", {{"dt", 0.01}}}, {"bodies", json::array({body})}}; }

std::string groundErrorField(const json& doc) {
  try {
    parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR);
  } catch (const InputError& e) {
    return e.field() + ": " + e.problem();
  }
  return "no error";
}

TEST(MeshGroundScene, TheKeyMakesAStaticMeshCollideAsItsTriangles) {
  const Scene plain = parseScene(groundSceneOf(groundPrism()), "test.json", RBSIM_TEST_DATA_DIR);
  ASSERT_EQ(plain.bodies.size(), 1u);
  EXPECT_TRUE(plain.bodies[0].sdf != nullptr);  // as before the key existed
  json body = groundPrism();
  body["collide_as"] = "triangles";
  const Scene ground = parseScene(groundSceneOf(body), "test.json", RBSIM_TEST_DATA_DIR);
  const BodyDef& def = ground.bodies[0];
  EXPECT_TRUE(def.sdf == nullptr);
  EXPECT_TRUE(def.triangles != nullptr);
  ASSERT_TRUE(def.shape.has_value());
  EXPECT_EQ(def.shape->type, ShapeType::Mesh);
}

TEST(MeshGroundScene, BadUsesNameTheirField) {
  const auto with = [](const auto& change) {
    json body = groundPrism();
    body["collide_as"] = "triangles";
    change(body);
    return groundErrorField(groundSceneOf(body));
  };
  EXPECT_EQ(with([](json& b) { b["collide_as"] = "hull"; }).rfind("bodies[0].collide_as:", 0), 0u);
  EXPECT_EQ(with([](json& b) { b["collide_as"] = 3; }).rfind("bodies[0].collide_as:", 0), 0u);
  EXPECT_EQ(with([](json& b) { b["static"] = false; }).rfind("bodies[0].collide_as:", 0), 0u);
  EXPECT_EQ(with([](json& b) { b["shape"] = {{"type", "box"}, {"extents", {1, 1, 1}}}; }).rfind("bodies[0].collide_as:", 0), 0u);
  EXPECT_EQ(with([](json& b) { b["sdf"] = {{"resolution", 32}}; }).rfind("bodies[0].sdf:", 0), 0u);
  EXPECT_EQ(with([](json& b) {
              b.erase("shape");
              b["shapes"] = json::array({{{"type", "box"}, {"extents", {1, 1, 1}}}});
            }).rfind("bodies[0].collide_as:", 0),
            0u);
}

// The demo (assets/scenes/mesh_ground.json): after 4 s every body is on the waving terrain, its
// centre above the surface under it (assets/meshes/make_terrain.py: y = 0.2 sin(kx) cos(kz),
// k = 2 pi / 6 m) and on the 12 x 12 m grid; those that cannot roll are nearly still (the ball and
// the capsule roll on between the hills, losing no energy to rolling).
TEST(MeshGroundScene, TheDemoSceneSettlesOnTheTerrain) {
  const Scene scene = loadScene(std::string(RBSIM_ASSET_DIR) + "/scenes/mesh_ground.json");
  World world = buildWorld(scene);
  const int steps = static_cast<int>(std::lround(4.0 / scene.settings.timeStep));
  for (int s = 0; s < steps; ++s) world.step();
  constexpr double k = 2.0 * 3.14159265358979323846 / 6.0;  // [1/m]
  for (const RigidBody& b : world.bodies()) {
    if (b.isStatic()) continue;
    const Vec3& x = b.position();
    EXPECT_GT(x.y(), 0.2 * std::sin(k * x.x()) * std::cos(k * x.z())) << b.name();
    EXPECT_LT(std::max(std::abs(x.x()), std::abs(x.z())), 6.0) << b.name();
    if (b.name() != "ball" && b.name() != "capsule") {
      EXPECT_LT(b.velocity().norm(), 0.05) << b.name();
    }
  }
}

}  // namespace
}  // namespace rbsim
