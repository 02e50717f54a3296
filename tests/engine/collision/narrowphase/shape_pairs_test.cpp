// Pair tests with a sphere or a capsule (collision/narrowphase/shape_pairs.h) against their
// analytic answers: normal from A to B, depth = overlap of the exact surfaces, points midway.
#include <cmath>

#include <gtest/gtest.h>

#include "collision/narrowphase/shape_pairs.h"

#include <random>

#include "collision/narrowphase/convex_convex.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/math/rotation.h"

namespace rbsim {
namespace {

PosedShape at(const Shape& s, const Vec3& x, const Mat3& R = Mat3::Identity()) { return {&s, R, x}; }

TEST(ShapePairs, SphereSphereIsExactAtAnyDistance) {
  const Shape a = Shape::sphere(0.5), b = Shape::sphere(0.25);
  const Vec3 dir = Vec3(1.0, 2.0, -2.0) / 3.0;
  for (const double gap : {-0.1, 0.0, 0.005}) {
    const ContactManifold m = collideRoundPair(at(a, Vec3::Zero()), at(b, dir * (0.75 + gap)), 0.01);
    ASSERT_EQ(m.count, 1) << gap;
    EXPECT_NEAR((m.normal - dir).norm(), 0.0, 1e-15);
    EXPECT_NEAR(m.points[0].depth, -gap, 1e-15);
    EXPECT_NEAR((m.points[0].position - dir * (0.5 + 0.5 * gap)).norm(), 0.0, 1e-15);
  }
  EXPECT_EQ(collideRoundPair(at(a, Vec3::Zero()), at(b, dir * 0.77), 0.01).count, 0);  // 2 cm apart
}

TEST(ShapePairs, SphereOnAPlaneTouchesAtOnePointUnderItsCentre) {
  const Shape s = Shape::sphere(0.5);
  const Plane ground;
  // However the ball has turned, its contact is at (x, 0, z) and its depth r - y.
  const Mat3 turned = rotationFromAxisAngle(Vec3(0.3, 1.1, -0.7));
  const ContactManifold m = collidePlaneShape(ground, at(s, Vec3(2.0, 0.49, -1.0), turned), 0.0);
  ASSERT_EQ(m.count, 1);
  EXPECT_EQ(m.normal, Vec3::UnitY());
  EXPECT_NEAR(m.points[0].depth, 0.01, 1e-15);
  EXPECT_NEAR((m.points[0].position - Vec3(2.0, -0.005, -1.0)).norm(), 0.0, 1e-15);
}

TEST(ShapePairs, ACapsuleLyingOnAPlaneTouchesAtBothCaps) {
  const Shape c = Shape::capsule(0.2, 0.5);
  const Mat3 lying = rotationFromAxisAngle(Vec3(0.0, 0.0, 0.5 * kPi));  // axis along -x
  const ContactManifold m = collidePlaneShape(Plane{}, at(c, Vec3(0.0, 0.2, 0.0), lying), 1e-12);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR(std::abs(m.points[0].position.x() - m.points[1].position.x()), 1.0, 1e-12);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(m.points[i].depth, 0.0, 1e-15);
  // Standing on a cap: one point.
  EXPECT_EQ(collidePlaneShape(Plane{}, at(c, Vec3(0.0, 0.7, 0.0)), 0.0).count, 1);
}

TEST(ShapePairs, ParallelCapsulesTouchAlongTheirOverlap) {
  const Shape a = Shape::capsule(0.1, 0.5), b = Shape::capsule(0.1, 0.5);
  // B lies on A, shifted 0.3 along the axis: they overlap from y = -0.2 to 0.5.
  const ContactManifold m = collideRoundPair(at(a, Vec3::Zero()), at(b, Vec3(0.19, 0.3, 0.0)), 0.0);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR((m.normal - Vec3::UnitX()).norm(), 0.0, 1e-15);
  const double y0 = m.points[0].position.y(), y1 = m.points[1].position.y();
  EXPECT_NEAR(std::min(y0, y1), -0.2, 1e-12);
  EXPECT_NEAR(std::max(y0, y1), 0.5, 1e-12);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(m.points[i].depth, 0.01, 1e-12);
  // Crossed capsules touch at one point, the closest points of their axes.
  const Mat3 crossed = rotationFromAxisAngle(Vec3(0.5 * kPi, 0.0, 0.0));
  const ContactManifold x = collideRoundPair(at(a, Vec3::Zero()), at(b, Vec3(0.15, 0.1, 0.0), crossed), 0.0);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR(x.points[0].depth, 0.05, 1e-12);
}

TEST(ShapePairs, SphereAgainstABoxFaceEdgeCornerAndInside) {
  const Shape box = Shape::box(Vec3(0.5, 0.5, 0.5)), ball = Shape::sphere(0.1);
  struct Case {
    Vec3 centre, normal;
    double depth;
  };
  const double s = std::sqrt(0.5), t = 1.0 / std::sqrt(3.0);
  const Case cases[] = {
      {Vec3(0.0, 0.58, 0.1), Vec3::UnitY(), 0.02},                                   // over the top face
      {Vec3(0.5 + 0.05 * s, 0.5 + 0.05 * s, 0.0), Vec3(s, s, 0.0), 0.05},            // over an edge
      {Vec3::Constant(0.5 + 0.09 * t), Vec3(t, t, t), 0.01},                          // over a corner
      {Vec3(0.0, 0.45, 0.0), Vec3::UnitY(), 0.15},                                    // centre inside
  };
  for (const Case& c : cases) {
    const ContactManifold m = collideRoundPair(at(box, Vec3::Zero()), at(ball, c.centre), 0.0);
    ASSERT_GE(m.count, 1) << c.centre.transpose();
    EXPECT_NEAR((m.normal - c.normal).norm(), 0.0, 1e-9) << c.centre.transpose();
    EXPECT_NEAR(m.points[0].depth, c.depth, 1e-9) << c.centre.transpose();
    // The same pair the other way round: the normal flips, the depth stays.
    const ContactManifold r = collideRoundPair(at(ball, c.centre), at(box, Vec3::Zero()), 0.0);
    ASSERT_GE(r.count, 1);
    EXPECT_NEAR((r.normal + c.normal).norm(), 0.0, 1e-9);
    EXPECT_NEAR(r.points[0].depth, c.depth, 1e-9);
  }
}

TEST(ShapePairs, ACapsuleLyingOnABoxTouchesAtTwoPoints) {
  const Shape box = Shape::box(Vec3(1.0, 0.5, 1.0)), capsule = Shape::capsule(0.1, 0.3);
  const Mat3 lying = rotationFromAxisAngle(Vec3(0.5 * kPi, 0.0, 0.0));  // axis along z
  const ContactManifold m = collideRoundPair(at(box, Vec3::Zero()), at(capsule, Vec3(0.2, 0.599, 0.0), lying), 0.0);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR((m.normal - Vec3::UnitY()).norm(), 0.0, 1e-9);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].depth, 0.001, 1e-9);
    EXPECT_NEAR(std::abs(m.points[i].position.z()), 0.3, 1e-9);
  }
}

// GJK and EPA climbing two large hulls' vertex graphs find what scanning every vertex finds.
TEST(ShapePairs, HillClimbingHullsCollideAsScannedOnes) {
  const Mesh mesh = makeUvSphere(0.5, 48, 24);
  const Shape hull = Shape::convexHull(mesh);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int touching = 0;
  for (int i = 0; i < 200; ++i) {
    const PosedShape a = at(hull, Vec3::Zero(), rotationFromAxisAngle(Vec3(u(rng), u(rng), u(rng))));
    const PosedShape b = at(hull, Vec3(u(rng), u(rng), u(rng)), rotationFromAxisAngle(Vec3(u(rng), u(rng), u(rng))));
    const std::vector<Vec3> va = worldHullVertices(a), vb = worldHullVertices(b);
    const ConvexContact scanned = collideConvex(va, vb, 0.01);
    const ConvexContact climbed = collideConvex(PosedHullSupport(a), va, PosedHullSupport(b), vb, 0.01);
    ASSERT_EQ(scanned.overlap, climbed.overlap) << i;
    EXPECT_NEAR(scanned.distance, climbed.distance, 1e-9) << i;
    EXPECT_NEAR(scanned.depth, climbed.depth, 1e-7) << i;
    ASSERT_EQ(scanned.manifold.count, climbed.manifold.count) << i;
    if (scanned.manifold.count > 0) {
      EXPECT_NEAR((scanned.manifold.normal - climbed.manifold.normal).norm(), 0.0, 1e-6) << i;
    }
    touching += scanned.overlap ? 1 : 0;
  }
  EXPECT_GT(touching, 50);  // both kinds of pair were tried
}

}  // namespace
}  // namespace rbsim
