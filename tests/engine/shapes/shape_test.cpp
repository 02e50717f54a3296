// Shapes (engine/include/rbsim/shapes/shape.h): support points against their definitions, hill climbing against
// a full scan, exact bounds, and the closed-form mass properties against the polyhedral integrals
// of fine meshes of the same solids.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "rbsim/body/shape_body.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/rotation.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {
namespace {

Vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

TEST(Shape, SupportPointsAreTheFurthestPointsOfEachSolid) {
  std::mt19937 rng(7);
  const Shape sphere = Shape::sphere(0.5), capsule = Shape::capsule(0.2, 0.4), box = Shape::box(Vec3(0.1, 0.2, 0.3));
  for (int i = 0; i < 200; ++i) {
    const Vec3 d = randomUnit(rng) * 3.0;  // not unit: support must not depend on |d|
    EXPECT_NEAR(d.normalized().dot(sphere.support(d)), 0.5, 1e-15);
    // A capsule's extent along u is h |u_y| + r.
    EXPECT_NEAR(d.normalized().dot(capsule.support(d)), 0.4 * std::abs(d.normalized().y()) + 0.2, 1e-15);
    EXPECT_NEAR(d.dot(box.support(d)), d.cwiseAbs().dot(Vec3(0.1, 0.2, 0.3)), 1e-15);
  }
}

TEST(Shape, HillClimbingFindsTheSameSupportAsAScan) {
  const Mesh mesh = makeUvSphere(1.0, 48, 24);  // 1106 vertices, welded to 1106 - seam copies
  const Shape hull = Shape::convexHull(mesh);
  ASSERT_GT(hull.hull->vertices.size(), kHillClimbMinVertices);
  std::mt19937 rng(3);
  unsigned hint = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 d = randomUnit(rng);
    double best = -INFINITY;
    for (const Vec3& p : mesh.vertices) best = std::max(best, p.dot(d));
    EXPECT_DOUBLE_EQ(hull.support(d, &hint).dot(d), best) << i;
  }
}

TEST(Shape, WorldBoundsAreTightAtEveryPose) {
  std::mt19937 rng(11);
  for (const Shape& s : {Shape::sphere(0.3), Shape::capsule(0.1, 0.5), Shape::box(Vec3(0.2, 0.4, 0.1))}) {
    for (int i = 0; i < 50; ++i) {
      const Mat3 R = rotationFromAxisAngle(randomUnit(rng) * (2.0 * kPi * std::uniform_real_distribution<>()(rng)));
      const Vec3 x(1.0, -2.0, 3.0);
      const auto [lo, hi] = s.worldBounds(R, x);
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = Vec3::Unit(k);
        // The bound on each side is the support point's coordinate: no looser, no tighter.
        EXPECT_NEAR(hi[k], (R * s.support(R.transpose() * e) + x)[k], 1e-12) << shapeTypeName(s.type);
        EXPECT_NEAR(lo[k], (R * s.support(-R.transpose() * e) + x)[k], 1e-12) << shapeTypeName(s.type);
      }
    }
  }
}

// The closed forms against the integrals of meshes fine enough to be within 1e-3 of the solid.
TEST(Shape, ClosedFormMassPropertiesMatchFineMeshes) {
  struct Case {
    Shape shape;
    Mesh mesh;
  };
  const Case cases[] = {{Shape::sphere(0.5), makeUvSphere(0.5, 256, 128)},
                        {Shape::capsule(0.2, 0.3), makeCapsule(0.2, 0.6, 256, 128)},
                        {Shape::box(Vec3(0.1, 0.2, 0.3)), makeBox(Vec3(0.2, 0.4, 0.6))}};
  for (const Case& c : cases) {
    const MassProperties fine = polyhedralMassProperties(c.mesh, 1000.0);
    const double volume = roundOrBoxVolume(c.shape);
    EXPECT_NEAR(fine.volume / volume, 1.0, 1e-3) << shapeTypeName(c.shape.type);
    const Mat3 exact = roundOrBoxInertia(c.shape, 1000.0 * volume);
    EXPECT_LT((fine.inertia - exact).norm() / exact.norm(), 1.5e-3) << shapeTypeName(c.shape.type);
    EXPECT_LT(fine.centerOfMass.norm(), 1e-12);
  }
  // And exactly the textbook values: 2/5 m r^2; a capsule of zero length is a sphere.
  EXPECT_DOUBLE_EQ(roundOrBoxInertia(Shape::sphere(0.5), 2.0)(0, 0), 0.2);
  EXPECT_DOUBLE_EQ(roundOrBoxInertia(Shape::capsule(0.5, 0.0), 2.0)(0, 0), 0.2);
  EXPECT_DOUBLE_EQ(roundOrBoxInertia(Shape::capsule(0.5, 0.0), 2.0)(1, 1), 0.2);
}

TEST(Shape, AMeshOfEightCornersIsABoxAndOthersAreHulls) {
  EXPECT_EQ(shapeOfMesh(makeBox(Vec3(1.0, 2.0, 3.0)), false).type, ShapeType::Box);
  EXPECT_EQ(shapeOfMesh(makeBox(Vec3(1.0, 2.0, 3.0)), false).halfExtents, Vec3(0.5, 1.0, 1.5));
  EXPECT_EQ(shapeOfMesh(makeBox(Vec3(1.0, 2.0, 3.0)), true).type, ShapeType::Mesh);
  Mesh skewed = makeBox(Vec3::Ones());
  skewed.vertices[0].x() -= 0.1;  // still 8 vertices, no longer a box
  EXPECT_EQ(shapeOfMesh(skewed, false).type, ShapeType::ConvexHull);
  EXPECT_EQ(shapeOfMesh(makeUvSphere(1.0, 8, 4), false).type, ShapeType::ConvexHull);
}

TEST(Shape, InvalidSizesAreRefused) {
  EXPECT_THROW(Shape::sphere(0.0), std::invalid_argument);
  EXPECT_THROW(Shape::sphere(NAN), std::invalid_argument);
  EXPECT_THROW(Shape::capsule(0.1, -1.0), std::invalid_argument);
  EXPECT_THROW(Shape::box(Vec3(1.0, 0.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(Shape::convexHull(Mesh{}), std::invalid_argument);
  EXPECT_THROW(shapeBodyDef(Shape::sphere(1.0), -1.0), std::invalid_argument);
}

TEST(Shape, RoundDistanceIsTheDistanceToTheSurface) {
  const Shape capsule = Shape::capsule(0.2, 0.5);
  auto [d, n] = capsule.roundDistance(Vec3(1.0, 0.3, 0.0));  // beside the cylinder
  EXPECT_DOUBLE_EQ(d, 0.8);
  EXPECT_EQ(n, Vec3::UnitX());
  std::tie(d, n) = capsule.roundDistance(Vec3(0.0, 1.0, 0.0));  // above the top cap
  EXPECT_DOUBLE_EQ(d, 0.3);
  EXPECT_EQ(n, Vec3::UnitY());
  std::tie(d, n) = Shape::sphere(1.0).roundDistance(Vec3(0.0, 0.0, 0.25));  // inside
  EXPECT_DOUBLE_EQ(d, -0.75);
}

}  // namespace
}  // namespace rbsim
