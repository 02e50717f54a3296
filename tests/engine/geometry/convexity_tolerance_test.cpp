// geometry/mesh.h convexityTolerance (issue 34): a mesh is convex within the rounding of float
// coordinates and of a hull builder's merged faces, and non-convex once a dent is deeper than that.
#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/box3d_convex_pile_hull.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/geometry/mesh_generators.h"
#include "io/obj_loader.h"

namespace rbsim {
namespace {

// The largest distance of a vertex outside a triangle's plane [m].
double worstOutside(const Mesh& mesh) {
  double worst = -INFINITY;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).normalized();
    for (const Vec3& p : mesh.vertices) worst = std::max(worst, n.dot(p - a));
  }
  return worst;
}

double diagonal(const Mesh& mesh) { return (mesh.boundsMax() - mesh.boundsMin()).norm(); }

// Every coordinate rounded to float, then moved one float step up or down (drawn from a seeded
// generator, so that faces' triangles tilt against each other), as a mesh written by float code.
Mesh floatJittered(Mesh mesh) {
  std::mt19937 bits(34);  // the standard fixes mt19937's sequence
  for (Vec3& p : mesh.vertices) {
    for (int i = 0; i < 3; ++i) p[i] = std::nextafter(static_cast<float>(p[i]), (bits() & 1) ? INFINITY : -INFINITY);
  }
  return mesh;
}

// An L-shaped prism 1 m x 1 m x 1 m whose upper arm is `notch` [m] narrower than its lower one.
Mesh lPrism(double notch) {
  const std::vector<Vec2> outline = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.0}, {0.5 - notch, 0.0}, {0.5 - notch, 0.5}, {-0.5, 0.5}};
  return makeExtrudedPolygon(outline, 1.0);
}

// A 1 m cube whose top face is pushed in to a point `depth` [m] deep at its centre.
Mesh dimpledCube(double depth) {
  Mesh cube = makeBox(Vec3::Ones());
  // makeBox's top (+y) face is the triangles {3, 7, 6} and {3, 6, 2}: corners 3, 7, 6, 2 in turn.
  cube.triangles.erase(std::remove_if(cube.triangles.begin(), cube.triangles.end(),
                                      [&](const Triangle& t) {
                                        return cube.vertices[t[0]].y() > 0.0 && cube.vertices[t[1]].y() > 0.0 &&
                                               cube.vertices[t[2]].y() > 0.0;
                                      }),
                       cube.triangles.end());
  const std::uint32_t c = static_cast<std::uint32_t>(cube.vertices.size());
  cube.vertices.emplace_back(0.0, 0.5 - depth, 0.0);
  cube.triangles.insert(cube.triangles.end(), {{c, 3, 7}, {c, 7, 6}, {c, 6, 2}, {c, 2, 3}});
  return cube;
}

TEST(ConvexityTolerance, IsTheLargerOfTheSizeTermAndTheFloatRoundingTerm) {
  const Mesh near = makeBox(Vec3::Ones());  // at the origin the size term decides
  EXPECT_DOUBLE_EQ(convexityTolerance(near), kConvexRelativeTolerance * std::sqrt(3.0));
  Mesh far = makeBox(Vec3::Ones());  // 10 km out, float keeps 1 mm: the rounding term decides
  translateMesh(far, -Vec3::Constant(1e4));
  EXPECT_DOUBLE_EQ(convexityTolerance(far), kConvexFloatTolerance * FLT_EPSILON * 3.0 * (1e4 + 0.5));
  EXPECT_GT(convexityTolerance(far), kConvexRelativeTolerance * diagonal(far));
  EXPECT_EQ(convexityTolerance(Mesh{}), 0.0);
}

TEST(ConvexityTolerance, BoxThreeDConvexPileHullIsConvex) {
  const Mesh hull = test::box3dConvexPileHull();
  const double outside = worstOutside(hull);
  EXPECT_NEAR(outside, 7.7e-5, 0.1e-5) << "the split quad's vertex, as issue 34 measured it";
  EXPECT_TRUE(isConvexSurface(hull, convexityTolerance(hull)));
  EXPECT_LT(outside, 0.125 * convexityTolerance(hull)) << "kept with a margin of 8";
  // The old tolerance, 1e-6 of the size, called it non-convex and gave each of 5120 bodies a grid.
  EXPECT_FALSE(isConvexSurface(hull, 1e-6 * diagonal(hull)));
}

TEST(ConvexityTolerance, FloatRoundedAndJitteredCubeStaysConvex) {
  const Mesh near = floatJittered(makeBox(Vec3::Ones()));
  EXPECT_GT(worstOutside(near), 0.0) << "the jitter bends the faces";
  EXPECT_TRUE(isConvexSurface(near, convexityTolerance(near)));
  // 10 km from its origin a float steps by 1 mm: the faces bend by more than the size term allows,
  // and the rounding term keeps the cube convex.
  Mesh farBox = makeBox(Vec3::Ones());
  translateMesh(farBox, -Vec3::Constant(1e4));
  const Mesh far = floatJittered(farBox);
  EXPECT_GT(worstOutside(far), kConvexRelativeTolerance * diagonal(far));
  EXPECT_FALSE(isConvexSurface(far, kConvexRelativeTolerance * diagonal(far)));
  EXPECT_TRUE(isConvexSurface(far, convexityTolerance(far)));
}

TEST(ConvexityTolerance, OneMillimetreNotchInAMetreBodyIsNonConvex) {
  const Mesh notched = lPrism(1e-3);
  // The inner corner lies 1 mm inside the hull's face x = 0.5; the step's face is 1 mm wide.
  EXPECT_FALSE(isConvexSurface(notched, convexityTolerance(notched)));
  // The same prism rounded to float and jittered keeps its notch.
  const Mesh jittered = floatJittered(notched);
  EXPECT_FALSE(isConvexSurface(jittered, convexityTolerance(jittered)));
}

TEST(ConvexityTolerance, DimpleDeeperThanTheToleranceIsNonConvex) {
  // Around the dimple's bottom the four triangles tilt by depth / 0.5 m, so the top's far corners
  // stand 2 x depth above their planes: the smallest dent whose every face plane is near the body.
  const double deep = 1e-3, shallow = 2.5e-5;
  EXPECT_NEAR(worstOutside(dimpledCube(deep)), 2.0 * deep, 1e-8);
  EXPECT_FALSE(isConvexSurface(dimpledCube(deep), convexityTolerance(dimpledCube(deep))));
  EXPECT_FALSE(isConvexSurface(floatJittered(dimpledCube(deep)), convexityTolerance(dimpledCube(deep))));
  // 2 x 2.5e-5 m = 5e-5 m, 2.9e-5 of the size: under the tolerance, rounding.
  EXPECT_LT(worstOutside(dimpledCube(shallow)), convexityTolerance(dimpledCube(shallow)));
  EXPECT_TRUE(isConvexSurface(dimpledCube(shallow), convexityTolerance(dimpledCube(shallow))));
}

TEST(ConvexityTolerance, NonConvexMeshesStayNonConvex) {
  const std::vector<Mesh> meshes = {makeTorus(1.0, 0.3, 48, 24), makeLetterU(1.0, 1.0, 0.25, 0.5), makeBowl(1.0, 0.1, 48, 12),
                                    loadObj(std::string(RBSIM_ASSET_DIR) + "/meshes/l_bracket.obj"),
                                    loadObj(std::string(RBSIM_ASSET_DIR) + "/meshes/t_handle.obj")};
  for (const Mesh& mesh : meshes) {
    EXPECT_FALSE(isConvexSurface(mesh, convexityTolerance(mesh))) << mesh.name;
    EXPECT_FALSE(isConvexSurface(floatJittered(mesh), convexityTolerance(mesh))) << mesh.name << " in float";
  }
  // And convex ones convex: a fine sphere, a box, a capsule.
  for (const Mesh& mesh : {makeUvSphere(1.0, 48, 24), makeBox(Vec3(1, 2, 3)), makeCapsule(0.5, 1.0, 48, 24)}) {
    EXPECT_TRUE(isConvexSurface(mesh, convexityTolerance(mesh))) << mesh.name;
  }
}

}  // namespace
}  // namespace rbsim
