// scene/: the parts of a scene that collision scenes use: planes, static bodies, springs and
// spawn blocks (many bodies from one template, reproducible from a seed).
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "test_util.h"

namespace rbsim {
namespace {

using nlohmann::json;
using test::allNear;

json collisionBoxBody(const std::string& name = "box") {
  return {{"name", name}, {"shape", {{"type", "box"}, {"extents", {1.0, 2.0, 3.0}}}}, {"mass", 2.0}};
}

Scene parseCollision(const json& doc) { return parseScene(doc, "test.json", RBSIM_TEST_DATA_DIR); }

std::string errorOf(const json& doc) {
  try {
    parseCollision(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << doc.dump();
  return "";
}

bool collisionContains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ScenePlanes, NormalIsADirectionAndTheOffsetComesFromThePoint) {
  const json doc = {{"bodies", {collisionBoxBody()}},
                    {"planes", {{{"normal", {0.0, 2.0, 0.0}}}, {{"normal", {-3.0, 0.0, 4.0}}, {"point", {1.0, 5.0, 2.0}}}}}};
  const Scene scene = parseCollision(doc);
  ASSERT_EQ(scene.planes.size(), 2u);
  EXPECT_TRUE(allNear(scene.planes[0].normal, Vec3::UnitY(), 0.0));
  EXPECT_EQ(scene.planes[0].offset, 0.0);
  EXPECT_TRUE(allNear(scene.planes[1].normal, Vec3(-0.6, 0.0, 0.8), 1e-15));
  EXPECT_NEAR(scene.planes[1].offset, -0.6 * 1.0 + 0.8 * 2.0, 1e-15);
  EXPECT_NEAR(scene.planes[1].signedDistance(Vec3(1.0, 5.0, 2.0)), 0.0, 1e-15);
  const World world = buildWorld(scene);
  EXPECT_EQ(world.planes().size(), 2u);
}

TEST(ScenePlanes, ZeroNormalIsRejected) {
  const std::string e = errorOf({{"bodies", {collisionBoxBody()}}, {"planes", {{{"normal", {0.0, 0.0, 0.0}}}}}});
  EXPECT_TRUE(collisionContains(e, "planes[0].normal")) << e;
  EXPECT_TRUE(collisionContains(e, "non-zero")) << e;
}

TEST(SceneStatic, AStaticBodyHasBoxExtentsAndCannotMove) {
  json wall = collisionBoxBody("wall");
  wall["static"] = true;
  const Scene scene = parseCollision({{"bodies", {wall}}});
  ASSERT_TRUE(scene.bodies[0].isStatic);
  ASSERT_TRUE(scene.bodies[0].shape.has_value());
  ASSERT_EQ(scene.bodies[0].shape->type, ShapeType::Box);
  EXPECT_TRUE(allNear(scene.bodies[0].shape->halfExtents, Vec3(0.5, 1.0, 1.5), 0.0));

  World world = buildWorld(scene);
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_TRUE(allNear(world.bodies()[0].position(), Vec3::Zero(), 0.0)) << "gravity does not move it";
  EXPECT_FALSE(world.bodies()[0].awake());

  wall["velocity"] = {1.0, 0.0, 0.0};
  const std::string e = errorOf({{"bodies", {wall}}});
  EXPECT_TRUE(collisionContains(e, "bodies[0].velocity")) << e;
  EXPECT_TRUE(collisionContains(e, "static")) << e;
}

// |x(0.75 s) - 0.5 cos(2 t)| for a 2 kg box on an 8 N/m zero-length spring from x = 0.5 m.
double springError(double dt) {
  json body = collisionBoxBody();
  body["position"] = {0.5, 0.0, 0.0};
  body["springs"] = {{{"anchor", {0.0, 0.0, 0.0}}, {"stiffness", 8.0}}};
  const json doc = {{"world", {{"gravity", {0.0, 0.0, 0.0}}, {"dt", dt}, {"integrator", "dlm"}}}, {"bodies", {body}}};
  World world = buildWorld(parseCollision(doc));
  EXPECT_EQ(springs(world).size(), 1u);
  while (world.time() < 0.75 - 0.5 * dt) world.step();
  return std::abs(world.bodies()[0].position().x() - 0.5 * std::cos(2.0 * world.time()));
}

TEST(SceneSprings, AZeroLengthSpringGivesSimpleHarmonicMotion) {
  // x(t) = 0.5 cos(2 t). The force is held over each step, so the error is first order in dt:
  // measured 2.2e-5 m at dt = 1e-4 s. Halving dt must halve it.
  const double coarse = springError(1e-4), fine = springError(5e-5);
  EXPECT_LT(coarse, 1e-4);
  EXPECT_NEAR(coarse / fine, 2.0, 0.1);
}

TEST(SceneSprings, NegativeDampingIsRejected) {
  json body = collisionBoxBody();
  body["springs"] = {{{"anchor", {0.0, 0.0, 0.0}}, {"stiffness", 8.0}, {"damping", -1.0}}};
  const std::string e = errorOf({{"bodies", {body}}});
  EXPECT_TRUE(collisionContains(e, "bodies[0].springs[0].damping")) << e;
}

json spawnBlock(int count, int seed) {
  return {{"count", count},
          {"seed", seed},
          {"name", "crate"},
          {"body", {{"shape", {{"type", "box"}, {"extents", {0.2, 0.2, 0.2}}}}, {"mass", 1.0}}},
          {"region", {{"min", {-1.0, 0.0, -1.0}}, {"max", {1.0, 2.0, 1.0}}}},
          {"speed", {0.5, 1.0}},
          {"angular_speed", {0.0, 3.0}}};
}

TEST(SceneSpawn, SameSeedSameBodiesInsideTheRegionWithSpeedsInRange) {
  const json doc = {{"spawn", {spawnBlock(50, 7)}}};
  const Scene a = parseCollision(doc), b = parseCollision(doc);
  ASSERT_EQ(a.bodies.size(), 50u);
  EXPECT_EQ(a.bodies[0].name, "crate_0");
  EXPECT_EQ(a.bodies[49].name, "crate_49");
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position, b.bodies[i].position);
    EXPECT_EQ(a.bodies[i].velocity, b.bodies[i].velocity);
    EXPECT_TRUE((a.bodies[i].position.array() >= Vec3(-1.0, 0.0, -1.0).array()).all());
    EXPECT_TRUE((a.bodies[i].position.array() <= Vec3(1.0, 2.0, 1.0).array()).all());
    EXPECT_GE(a.bodies[i].velocity.norm(), 0.5 - 1e-12);
    EXPECT_LE(a.bodies[i].velocity.norm(), 1.0 + 1e-12);
    EXPECT_LE(a.bodies[i].angularVelocity.norm(), 3.0 + 1e-12);
    EXPECT_NEAR(a.bodies[i].orientation.norm(), 1.0, 1e-12);
    EXPECT_EQ(a.bodies[i].mesh, a.bodies[0].mesh) << "one mesh shared by the block";
  }
  const Scene other = parseCollision({{"spawn", {spawnBlock(50, 8)}}});
  EXPECT_NE(other.bodies[0].position, a.bodies[0].position) << "the seed matters";
}

TEST(SceneSpawn, SpringsAreCopiedToEveryInstance) {
  json block = spawnBlock(3, 1);
  block["body"]["springs"] = {{{"anchor", {0.0, 1.0, 0.0}}, {"stiffness", 2.0}}};
  const Scene scene = parseCollision({{"bodies", {collisionBoxBody()}}, {"spawn", {block}}});
  ASSERT_EQ(scene.bodies.size(), 4u);
  ASSERT_EQ(scene.springs.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(scene.springs[i].body, sceneBodyId(i + 1));
}

TEST(SceneSpawn, ErrorsNameTheSpawnPath) {
  json badMass = spawnBlock(3, 1);
  badMass["body"]["mass"] = -1.0;
  std::string e = errorOf({{"spawn", {badMass}}});
  EXPECT_TRUE(collisionContains(e, "spawn[0].body.mass")) << e;
  json badRange = spawnBlock(3, 1);
  badRange["speed"] = {2.0, 1.0};
  e = errorOf({{"spawn", {badRange}}});
  EXPECT_TRUE(collisionContains(e, "spawn[0].speed")) << e;
  json clash = spawnBlock(3, 1);
  e = errorOf({{"bodies", {collisionBoxBody("crate_1")}}, {"spawn", {clash}}});
  EXPECT_TRUE(collisionContains(e, "duplicate body name \"crate_1\"")) << e;
}

}  // namespace
}  // namespace rbsim
