// scene/body_parser.h ShapeCache (issue 34): bodies of one shape share one mesh, one hull, one
// signed distance grid and one mass computation, in the scene and in the World built from it; and
// the convexity a scene's mesh is judged with (geometry/mesh.h convexityTolerance).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/box3d_convex_pile_hull.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene.h"
#include "test_util.h"

namespace rbsim {
namespace {

using nlohmann::json;

// A folder under the system temporary directory, removed with the test.
class TempFolder {
 public:
  TempFolder() : path_(std::filesystem::temp_directory_path() / test::uniqueTempName("shapes")) {
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file) << text;
    return file.string();
  }

 private:
  std::filesystem::path path_;
};

std::string objText(const Mesh& mesh) {
  std::string text;
  char line[128];
  for (const Vec3& p : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
    text += line;
  }
  for (const Triangle& t : mesh.triangles) {
    text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
  }
  return text;
}

// An L-shaped prism 1 m x 1 m x 1 m whose upper arm is 1 mm narrower than its lower one.
Mesh notchedPrism() {
  const double notch = 1e-3;
  return makeExtrudedPolygon({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.0}, {0.5 - notch, 0.0}, {0.5 - notch, 0.5}, {-0.5, 0.5}}, 1.0);
}

json meshBody(const std::string& file, double x, double density = 1000.0) {
  return {{"shape", {{"type", "mesh"}, {"file", file}}}, {"density", density}, {"position", {x, 2.0, 0.0}}};
}

constexpr int kCopies = 64;

TEST(ShapeSharing, BodiesOfOneObjShareOneMeshHullAndMassComputation) {
  const TempFolder folder;
  folder.write("hull.obj", test::box3dConvexPileHullObj());
  json bodies = json::array();
  for (int i = 0; i < kCopies; ++i) bodies.push_back(meshBody(i % 2 == 0 ? "hull.obj" : "./sub/../hull.obj", 4.0 * i));
  json scaled = meshBody("hull.obj", -10.0);
  scaled["shape"]["scale"] = 0.5;
  bodies.push_back(scaled);
  bodies.push_back(meshBody("hull.obj", -20.0, 500.0));
  const Scene scene = loadScene(folder.write("pile.json", json{{"bodies", bodies}}.dump()));
  ASSERT_EQ(scene.bodies.size(), kCopies + 2u);

  const BodyDef& first = scene.bodies[0];
  ASSERT_TRUE(first.mesh && first.fileFrame.mesh && first.shape && first.shape->hull);
  EXPECT_EQ(first.shape->type, ShapeType::ConvexHull);
  EXPECT_EQ(first.sdf, nullptr) << "convex within the float hull's rounding: no grid";
  for (int i = 1; i < kCopies; ++i) {
    const BodyDef& def = scene.bodies[i];
    EXPECT_EQ(def.mesh.get(), first.mesh.get()) << i;
    EXPECT_EQ(def.fileFrame.mesh.get(), first.fileFrame.mesh.get()) << i;
    ASSERT_TRUE(def.shape) << i;
    EXPECT_EQ(def.shape->hull.get(), first.shape->hull.get()) << i;
    EXPECT_EQ(def.mass, first.mass) << i;
    EXPECT_EQ(def.inertiaBody, first.inertiaBody) << i;
    EXPECT_EQ(def.position.x(), 4.0 * i) << "the pose stays the body's own";
  }
  // A scale is another shape; another density the same geometry with another mass.
  const BodyDef& half = scene.bodies[kCopies];
  EXPECT_NE(half.mesh.get(), first.mesh.get());
  EXPECT_NEAR(half.mass, first.mass / 8.0, 1e-9 * first.mass);
  const BodyDef& light = scene.bodies[kCopies + 1];
  EXPECT_NEAR(light.mass, first.mass / 2.0, 1e-9 * first.mass);
  EXPECT_TRUE(test::allNear(light.inertiaBody, first.inertiaBody / 2.0, 1e-9 * first.inertiaBody.norm()));

  // The World keeps what the scene shares: one mesh and one hull for every copy.
  World world = buildWorld(scene);
  for (int i = 1; i < kCopies; ++i) {
    EXPECT_EQ(&world.body(world.idAt(i)).mesh(), &world.body(world.idAt(0)).mesh()) << i;
    EXPECT_EQ(world.body(world.idAt(i)).shape().hull.get(), world.body(world.idAt(0)).shape().hull.get()) << i;
  }
}

TEST(ShapeSharing, NonConvexBodiesShareOneGridAndItsSamples) {
  const TempFolder folder;
  folder.write("notched.obj", objText(notchedPrism()));
  json bodies = json::array();
  for (int i = 0; i < 8; ++i) bodies.push_back(meshBody("notched.obj", 2.0 * i));
  const Scene scene = loadScene(folder.write("notched.json", json{{"bodies", bodies}}.dump()));
  const BodyDef& first = scene.bodies[0];
  ASSERT_NE(first.sdf, nullptr) << "a 1 mm notch in a 1 m body is a dent, not rounding";
  ASSERT_NE(first.surfaceSamples, nullptr);
  EXPECT_EQ(first.shape->type, ShapeType::Mesh);
  for (std::size_t i = 1; i < scene.bodies.size(); ++i) {
    EXPECT_EQ(scene.bodies[i].sdf.get(), first.sdf.get()) << i;
    EXPECT_EQ(scene.bodies[i].surfaceSamples.get(), first.surfaceSamples.get()) << i;
    EXPECT_EQ(scene.bodies[i].shape->hull.get(), first.shape->hull.get()) << i;
  }
}

TEST(ShapeSharing, ListedAndSpawnedBodiesSharePrimitiveShapes) {
  const json box = {{"type", "box"}, {"extents", {1.0, 1.0, 1.0}}};
  const json sphere = {{"type", "sphere"}, {"radius", 0.4}};
  json bodies = json::array();
  for (int i = 0; i < 4; ++i) {
    bodies.push_back({{"shape", box}, {"density", 100}, {"position", {2.0 * i, 0.5, 0.0}}});
    bodies.push_back({{"shape", sphere}, {"density", 100}, {"position", {2.0 * i, 3.0, 0.0}}, {"static", i == 0}});
  }
  const json spawn = {{"count", 5}, {"body", {{"shape", box}, {"density", 100}}},
                      {"region", {{"min", {0.0, 5.0, 0.0}}, {"max", {4.0, 9.0, 4.0}}}}};
  const Scene scene = parseScene(json{{"bodies", bodies}, {"spawn", {spawn}}}, "test.json", RBSIM_TEST_DATA_DIR);
  ASSERT_EQ(scene.bodies.size(), 13u);
  std::set<const Mesh*> meshes;
  for (const BodyDef& def : scene.bodies) meshes.insert(def.mesh.get());
  EXPECT_EQ(meshes.size(), 2u) << "one box mesh and one sphere mesh for 13 bodies";
  EXPECT_EQ(scene.bodies.back().mesh.get(), scene.bodies[0].mesh.get()) << "the spawned box is the listed box";
  EXPECT_TRUE(scene.bodies[2].isStatic == false && scene.bodies[1].isStatic) << "flags stay per body";
}

TEST(ShapeSharing, AMissingMeshFileIsReportedAtTheFirstBodyNamingIt) {
  const TempFolder folder;
  json bodies = json::array({meshBody("missing.obj", 0.0), meshBody("missing.obj", 2.0)});
  try {
    loadScene(folder.write("missing.json", json{{"bodies", bodies}}.dump()));
    ADD_FAILURE() << "no error for a missing mesh file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "bodies[0].shape.file");
  }
}

}  // namespace
}  // namespace rbsim
