// rbsim/scene/cook.h (issue 58, "Parse, cook and present apart"): the parser describes a scene
// without building a grid or a triangle hierarchy, cookScene builds each distinct shape's once,
// and a SceneCache kept across descriptions of one document (a compared phase's worlds) cooks a
// shape once for all of them. Cooked from a description or loaded whole, a scene steps the same,
// bit for bit.
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/cook.h"
#include "rbsim/scene/scene.h"

namespace rbsim {
namespace {

using nlohmann::json;

// Three tori (closed and non-convex: a grid each, one shape), an implicit cup, a sphere (convex:
// nothing to cook), a static L bracket from a file colliding as its triangles, and a ground.
json sceneDocument() {
  json bodies = json::array();
  for (int i = 0; i < 3; ++i) {
    bodies.push_back({{"name", "torus" + std::to_string(i)},
                      {"shape", {{"type", "torus"}, {"major_radius", 0.3}, {"minor_radius", 0.1}}},
                      {"density", 100},
                      {"position", {0.9 * i, 0.6, 0.0}},
                      {"orientation", {{"axis_angle_deg", {1, 0, 0, 80}}}}});
  }
  bodies.push_back({{"name", "cup"},
                    {"shape", {{"type", "csg"}, {"op", "difference"}, {"resolution", 20},
                               {"a", {{"type", "implicit"}, {"function", "sphere"}, {"radius", 0.3}}},
                               {"b", {{"type", "implicit"}, {"function", "sphere"}, {"radius", 0.25},
                                      {"position", {0.0, 0.1, 0.0}}}}}},
                    {"density", 100},
                    {"position", {-1.0, 0.8, 0.0}}});
  bodies.push_back({{"name", "ball"}, {"shape", {{"type", "sphere"}, {"radius", 0.2}}}, {"density", 100}, {"position", {0.5, 1.8, 0.1}}});
  bodies.push_back({{"name", "bracket"},
                    {"shape", {{"type", "mesh"}, {"file", "concave_prism.obj"}}},
                    {"collide_as", "triangles"}, {"mass", 10},
                    {"static", true},
                    {"position", {0.0, 0.0, 1.5}}});
  return {{"world", {{"dt", 1.0 / 240.0}, {"duration", 0.5}}},
          {"planes", {{{"normal", {0, 1, 0}}}}},
          {"bodies", bodies}};
}

Scene describe(const json& document, SceneCache* cache = nullptr) {
  return describeScene(document, "cook.json", RBSIM_TEST_DATA_DIR, cache);
}

TEST(Cook, TheParserBuildsNoGridNoSamplesNoSolidAndNoHierarchy) {
  const Scene scene = describe(sceneDocument());
  ASSERT_EQ(scene.bodies.size(), 6u);
  for (const BodyDef& def : scene.bodies) {
    EXPECT_EQ(def.sdf, nullptr) << def.name;
    EXPECT_EQ(def.surfaceSamples, nullptr) << def.name;
    EXPECT_EQ(def.implicit, nullptr) << def.name;
    EXPECT_EQ(def.triangles, nullptr) << def.name;
    EXPECT_TRUE(def.mesh && def.shape) << def.name << ": meshes and collision shapes are described";
  }
  // One request per distinct shape: the tori's grid, the cup's solid, the bracket's hierarchy.
  ASSERT_EQ(scene.cooking.size(), 3u);
  EXPECT_EQ(scene.cooking[0].kind, CookRequest::Kind::Grid);
  EXPECT_EQ(scene.cooking[0].mesh.get(), scene.bodies[0].mesh.get());
  EXPECT_EQ(scene.cooking[1].kind, CookRequest::Kind::Implicit);
  EXPECT_EQ(scene.cooking[2].kind, CookRequest::Kind::Triangles);
  EXPECT_EQ(scene.bodies[5].shape->type, ShapeType::Mesh);
  EXPECT_THROW(buildWorld(scene), std::logic_error) << "a World needs the cooked scene";
}

TEST(Cook, CookingGivesEachShapeOneGridSharedByItsBodies) {
  Scene scene = describe(sceneDocument());
  SceneCache cache;
  cookScene(scene, &cache);
  EXPECT_TRUE(scene.cooking.empty());
  EXPECT_EQ(cache.shapesCooked(), 3u);
  ASSERT_NE(scene.bodies[0].sdf, nullptr);
  ASSERT_NE(scene.bodies[0].triangles, nullptr);
  for (int i = 1; i < 3; ++i) {
    EXPECT_EQ(scene.bodies[i].sdf.get(), scene.bodies[0].sdf.get()) << i;
    EXPECT_EQ(scene.bodies[i].surfaceSamples.get(), scene.bodies[0].surfaceSamples.get()) << i;
    EXPECT_EQ(scene.bodies[i].triangles.get(), scene.bodies[0].triangles.get()) << i;
  }
  EXPECT_TRUE(scene.bodies[3].sdf && scene.bodies[3].implicit && scene.bodies[3].surfaceSamples);
  EXPECT_TRUE(!scene.bodies[4].sdf && !scene.bodies[4].triangles) << "a sphere has nothing to cook";
  EXPECT_TRUE(scene.bodies[5].triangles && !scene.bodies[5].sdf) << "a mesh ground has its hierarchy only";
}

// The grid a torus cooks to: its lattice, every value, and the samples.
void expectSameGrid(const BodyDef& a, const BodyDef& b) {
  ASSERT_TRUE(a.sdf && b.sdf);
  ASSERT_EQ(a.sdf->dims(), b.sdf->dims());
  EXPECT_EQ(a.sdf->cellSize(), b.sdf->cellSize());
  EXPECT_EQ(a.sdf->origin(), b.sdf->origin());
  for (int k = 0; k < a.sdf->dims().z(); ++k) {
    for (int j = 0; j < a.sdf->dims().y(); ++j) {
      for (int i = 0; i < a.sdf->dims().x(); ++i) ASSERT_EQ(a.sdf->value(i, j, k), b.sdf->value(i, j, k));
    }
  }
  EXPECT_EQ(*a.surfaceSamples, *b.surfaceSamples);
}

TEST(Cook, ADescriptionCookedStepsAsTheSceneLoadedWhole) {
  const Scene whole = parseScene(sceneDocument(), "cook.json", RBSIM_TEST_DATA_DIR);
  Scene cooked = describe(sceneDocument());
  cookScene(cooked);
  expectSameGrid(whole.bodies[0], cooked.bodies[0]);
  expectSameGrid(whole.bodies[3], cooked.bodies[3]);
  World a = buildWorld(whole), b = buildWorld(cooked);
  for (std::uint64_t s = 0; s < whole.stepCount(); ++s) {
    a.step();
    b.step();
  }
  for (std::size_t i = 0; i < a.bodies().size(); ++i) {
    EXPECT_EQ(a.bodies()[i].position(), b.bodies()[i].position()) << i;
    EXPECT_EQ(a.bodies()[i].orientation().coeffs(), b.bodies()[i].orientation().coeffs()) << i;
  }
  EXPECT_LT(a.bodies()[0].position().y(), 0.6) << "the tori fell: the steps compared did something";
}

TEST(Cook, OneCacheCooksAShapeOnceForEveryDescriptionOfTheDocument) {
  SceneCache cache;
  std::set<const SignedDistanceGrid*> grids;
  // Four values of a key no shape reads: the shapes are described once and cooked once.
  for (const char* integrator : {"euler-quat", "dlm", "rk4", "symplectic-euler"}) {
    json document = sceneDocument();
    document["world"]["integrator"] = integrator;
    Scene scene = describe(document, &cache);
    EXPECT_EQ(scene.cooking.size(), 3u) << integrator << ": each description lists its shapes' requests";
    cookScene(scene, &cache);
    grids.insert(scene.bodies[0].sdf.get());
    grids.insert(scene.bodies[3].sdf.get());
  }
  EXPECT_EQ(cache.shapesDescribed(), 4u) << "the tori, the cup, the ball and the bracket";
  EXPECT_EQ(cache.shapesCooked(), 3u);
  EXPECT_EQ(grids.size(), 2u) << "one torus grid and one cup grid for four scenes";

  // Another mass is another description of the same mesh: its grid is found by the mesh's content.
  json heavier = sceneDocument();
  for (int i = 0; i < 3; ++i) heavier["bodies"][i]["density"] = 400;
  Scene scene = describe(heavier, &cache);
  cookScene(scene, &cache);
  EXPECT_EQ(cache.shapesDescribed(), 5u);
  EXPECT_EQ(cache.shapesCooked(), 3u);
  EXPECT_EQ(grids.count(scene.bodies[0].sdf.get()), 1u);

  // Another resolution is another grid.
  json finer = sceneDocument();
  for (int i = 0; i < 3; ++i) finer["bodies"][i]["sdf"] = {{"resolution", 24}};
  scene = describe(finer, &cache);
  cookScene(scene, &cache);
  EXPECT_EQ(cache.shapesCooked(), 4u);
  EXPECT_EQ(grids.count(scene.bodies[0].sdf.get()), 0u);
  EXPECT_EQ(scene.bodies[0].sdf->dims().maxCoeff(), 24 + 2 * SdfGridOptions().paddingCells + 1);
}

TEST(Cook, SpawnedPrototypesAreCookedToo) {
  json document = sceneDocument();
  document["spawn"] = {{{"name", "rain"}, {"period", 0.25}, {"count", 2},
                        {"body", {{"shape", {{"type", "torus"}, {"major_radius", 0.3}, {"minor_radius", 0.1}}}, {"density", 100}}},
                        {"region", {{"min", {0, 2, 0}}, {"max", {1, 3, 1}}}}}};
  Scene scene = describe(document);
  ASSERT_EQ(scene.spawners.size(), 1u);
  EXPECT_EQ(scene.spawners[0].prototype.sdf, nullptr);
  cookScene(scene);
  EXPECT_EQ(scene.spawners[0].prototype.sdf.get(), scene.bodies[0].sdf.get()) << "the listed tori's shape";
}

TEST(Cook, TheSdfSliceIsCheckedAgainstTheGridBeforeItIsBuilt) {
  json document = sceneDocument();
  document["view"] = {{"sdf_slice", {{"body", "torus1"}, {"axis", "y"}, {"offset", 0.0}}}};
  EXPECT_NO_THROW(describe(document));
  document["view"]["sdf_slice"]["offset"] = 5.0;
  try {
    describe(document);
    ADD_FAILURE() << "an offset outside the grid";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "view.sdf_slice.offset");
  }
  document["view"]["sdf_slice"] = {{"body", "bracket"}};
  EXPECT_THROW(describe(document), InputError) << "a mesh ground has no grid";
}

}  // namespace
}  // namespace rbsim
