// collision/shape_queries.h: the signed distance and the ray cast of every shape type, checked
// against independent answers: closed forms, the same solid written as another type (a box as a
// hull, a ball and a capsule as rounded boxes), and sphere tracing along the ray on the distance.
// Hulls answer through GJK and EPA, to 1e-9 m.
#include "rbsim/collision/shape_queries.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/geometry/mesh.h"
#include "rbsim/geometry/mesh_generators.h"

namespace rbsim {
namespace {

// A convex pentagonal prism, irregular, with no face parallel to another but the caps.
Shape prism() {
  const std::vector<Vec2> outline{{0.5, -0.1}, {0.3, 0.45}, {-0.25, 0.4}, {-0.45, -0.05}, {-0.1, -0.4}};
  return Shape::convexHull(makeExtrudedPolygon(outline, 0.6));
}

std::vector<Shape> everyConvexShape() {
  return {Shape::sphere(0.4),
          Shape::capsule(0.25, 0.35),
          Shape::box(Vec3(0.5, 0.2, 0.3)),
          Shape::roundedBox(Vec3(0.3, 0.1, 0.2), 0.08),
          Shape::roundedBox(Vec3(0.4, 0.0, 0.3), 0.05),  // a slab: the flat core's edge case
          prism()};
}

// Sphere tracing (Hart 1996): step along the ray by the distance, which no surface point is
// nearer than; converges on the first hit of a convex solid.
std::optional<double> traced(const Shape& shape, const Vec3& o, const Vec3& d, double maxFraction) {
  double t = 0.0;
  for (int i = 0; i < 100000 && t <= maxFraction; ++i) {
    const double distance = signedDistance(shape, o + t * d).distance;
    if (distance < 1e-13) return t;
    t += distance / d.norm();
  }
  return std::nullopt;
}

TEST(ShapeQueries, DistancesMatchClosedForms) {
  const Shape ball = Shape::sphere(0.4);
  EXPECT_NEAR(signedDistance(ball, Vec3(1.0, 0.0, 0.0)).distance, 0.6, 1e-15);
  EXPECT_NEAR(signedDistance(ball, Vec3(0.0, -0.1, 0.0)).distance, -0.3, 1e-15);
  const Shape box = Shape::box(Vec3(0.5, 0.2, 0.3));
  // Outside a corner: to the corner; inside: to the nearest face.
  EXPECT_NEAR(signedDistance(box, Vec3(0.8, 0.6, 0.3)).distance, 0.5, 1e-15);
  const ShapeDistance inside = signedDistance(box, Vec3(0.1, 0.15, 0.0));
  EXPECT_NEAR(inside.distance, -0.05, 1e-15);
  EXPECT_TRUE(inside.normal.isApprox(Vec3::UnitY()));
  const Shape capsule = Shape::capsule(0.25, 0.35);
  EXPECT_NEAR(signedDistance(capsule, Vec3(0.0, 1.0, 0.0)).distance, 1.0 - 0.35 - 0.25, 1e-15);
  EXPECT_NEAR(signedDistance(capsule, Vec3(0.3, 0.1, -0.4)).distance, 0.5 - 0.25, 1e-15);
}

// The same solid through two types' code: a box and the hull of its mesh, a ball and a rounded
// box with no core, a capsule and a rounded box whose core is a segment.
TEST(ShapeQueries, OneSolidAnswersAlikeWhateverItsType) {
  const Vec3 h(0.5, 0.2, 0.3);
  const std::vector<std::pair<Shape, Shape>> pairs{
      {Shape::box(h), Shape::convexHull(makeBox(2.0 * h))},
      {Shape::sphere(0.3), Shape::roundedBox(Vec3::Zero(), 0.3)},
      {Shape::capsule(0.2, 0.4), Shape::roundedBox(Vec3(0.0, 0.4, 0.0), 0.2)}};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const auto& [a, b] : pairs) {
    for (int trial = 0; trial < 2000; ++trial) {
      const Vec3 p(u(random), u(random), u(random));
      const ShapeDistance da = signedDistance(a, p), db = signedDistance(b, p);
      EXPECT_NEAR(da.distance, db.distance, 1e-9) << shapeTypeName(a.type) << " at " << p.transpose();
      const Vec3 d(u(random), u(random), u(random));
      const auto ra = rayCast(a, p, d, 3.0), rb = rayCast(b, p, d, 3.0);
      ASSERT_EQ(ra.has_value(), rb.has_value()) << shapeTypeName(a.type) << " from " << p.transpose();
      if (!ra) continue;
      EXPECT_NEAR(ra->fraction, rb->fraction, 1e-9);
      if (ra->fraction > 0.0) {
        EXPECT_LT((ra->normal - rb->normal).norm(), 1e-6) << shapeTypeName(a.type);
      }
    }
  }
}

// Every hit is on the surface, with the distance's normal there, and no earlier point of the ray
// is inside: the first hit, found again by sphere tracing. Misses are misses for the tracer too.
TEST(ShapeQueries, RayHitsAreTheFirstSurfacePoint) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Shape& shape : everyConvexShape()) {
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      const Vec3 o = 1.5 * Vec3(u(random), u(random), u(random));
      const Vec3 d = 1.5 * (0.3 * Vec3(u(random), u(random), u(random)) - o);  // towards the body, roughly
      const auto hit = rayCast(shape, o, d, 1.0);
      const auto expected = traced(shape, o, d, 1.0);
      ASSERT_EQ(hit.has_value(), expected.has_value()) << shapeTypeName(shape.type) << " from " << o.transpose();
      if (!hit) continue;
      ++hits;
      EXPECT_NEAR(hit->fraction, *expected, 1e-7) << shapeTypeName(shape.type);
      const ShapeDistance at = signedDistance(shape, o + hit->fraction * d);
      if (hit->fraction == 0.0) continue;  // started inside
      // Closed forms land on the surface to rounding; a hull's GJK to its tolerance.
      EXPECT_NEAR(at.distance, 0.0, shape.type == ShapeType::ConvexHull ? 1e-9 : 1e-12) << shapeTypeName(shape.type);
      EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-12);
      EXPECT_LT(hit->normal.dot(d), 0.0) << "the ray enters against the outward normal";
    }
    EXPECT_GT(hits, 1000) << shapeTypeName(shape.type) << ": the test must hit often";
  }
}

// The normal is the gradient of the distance: checked by central differences away from edges.
TEST(ShapeQueries, NormalIsTheDistanceGradient) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  constexpr double kStep = 1e-6;  // [m]
  for (const Shape& shape : everyConvexShape()) {
    for (int trial = 0; trial < 500; ++trial) {
      const Vec3 p = Vec3(u(random), u(random), u(random));
      Vec3 gradient;
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = kStep * Vec3::Unit(k);
        gradient[k] = (signedDistance(shape, p + e).distance - signedDistance(shape, p - e).distance) / (2.0 * kStep);
      }
      // Where the distance has a kink (inside, equidistant from two faces) the gradient is not unit.
      if (std::abs(gradient.norm() - 1.0) > 1e-6) continue;
      EXPECT_LT((signedDistance(shape, p).normal - gradient).norm(), 1e-5) << shapeTypeName(shape.type) << " at " << p.transpose();
    }
  }
}

TEST(ShapeQueries, ARayFromInsideHitsAtOnceAndAZeroDirectionMisses) {
  const Shape box = Shape::box(Vec3(0.5, 0.2, 0.3));
  const auto hit = rayCast(box, Vec3(0.0, 0.15, 0.0), Vec3(1.0, 0.0, 0.0));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->fraction, 0.0);
  EXPECT_TRUE(hit->normal.isApprox(Vec3::UnitY()));
  EXPECT_FALSE(rayCast(box, Vec3(2.0, 0.0, 0.0), Vec3::Zero()));
  const auto down = rayCast(box, Vec3(0.1, 1.2, 0.0), Vec3(0.0, -2.0, 0.0));
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->fraction, 0.5, 1e-15);
  EXPECT_FALSE(rayCast(box, Vec3(0.1, 1.2, 0.0), Vec3(0.0, -2.0, 0.0), 0.49)) << "beyond maxFraction";
}

TEST(ShapeQueries, AMeshShapeSendsTheCallerToItsSolid) {
  const Shape mesh = Shape::mesh(makeTorus(0.5, 0.1, 16, 8));
  EXPECT_THROW(signedDistance(mesh, Vec3::Zero()), std::invalid_argument);
  EXPECT_THROW(rayCast(mesh, Vec3::Zero(), Vec3::UnitX()), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim
