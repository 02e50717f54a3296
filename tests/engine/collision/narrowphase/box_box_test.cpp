// collision/narrowphase/box_box: SAT with face preference and clipped manifolds: separated,
// penetrating and resting boxes with known points, edge-on-edge crossing boxes, speculative
// margins, box recognition, and random pairs checked against the geometry.
#include "collision/narrowphase/box_box.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "narrowphase_test_util.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::makeOrientedBox;
using test::rotationAbout;

const Vec3 kHalf = Vec3::Constant(0.5);

bool boxHolds(const ContactManifold& m, const Vec3& p, double tol = 1e-12) {
  for (int i = 0; i < m.count; ++i) {
    if ((m.points[i].position - p).norm() <= tol) return true;
  }
  return false;
}

TEST(CollideBoxes, SeparatedCubesHaveNoContact) {
  const BoxBoxResult r = collideBoxes(makeOrientedBox(Vec3::Zero(), kHalf), makeOrientedBox(Vec3(1.5, 0.3, 0), kHalf));
  EXPECT_EQ(r.manifold.count, 0);
  EXPECT_NEAR(r.separation, 0.5, 1e-15);
}

TEST(CollideBoxes, PenetratingCubesGiveTheOverlapFaceCorners) {
  const BoxBoxResult r = collideBoxes(makeOrientedBox(Vec3::Zero(), kHalf), makeOrientedBox(Vec3(0.9, 0, 0), kHalf));
  EXPECT_EQ(r.axis, SatAxisKind::FaceA);
  EXPECT_NEAR(r.separation, -0.1, 1e-15);
  EXPECT_TRUE(allNear(r.manifold.normal, Vec3::UnitX(), 0.0));
  ASSERT_EQ(r.manifold.count, 4);
  for (double y : {-0.5, 0.5}) {
    for (double z : {-0.5, 0.5}) EXPECT_TRUE(boxHolds(r.manifold, Vec3(0.45, y, z))) << y << " " << z;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.manifold.points[i].depth, 0.1, 1e-15);
}

TEST(CollideBoxes, NormalPointsFromAToBWhicheverFaceIsTheReference) {
  // B (the bigger box) owns the reference face; the normal still points from A to B.
  const BoxBoxResult r = collideBoxes(makeOrientedBox(Vec3(0, 0.98, 0), kHalf),
                                      makeOrientedBox(Vec3::Zero(), Vec3(2, 0.5, 2)));
  EXPECT_TRUE(allNear(r.manifold.normal, -Vec3::UnitY(), 0.0));
  ASSERT_EQ(r.manifold.count, 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.manifold.points[i].depth, 0.02, 1e-15);
}

TEST(CollideBoxes, BoxRestingFaceDownHasFourPointsAtItsCorners) {
  // A: a 2 x 1 x 2 slab with its top at y = 0.5; B: a unit cube sunk 1 cm into it, off-centre.
  const OrientedBox slab = makeOrientedBox(Vec3::Zero(), Vec3(1, 0.5, 1));
  const OrientedBox cube = makeOrientedBox(Vec3(0.2, 0.99, -0.1), kHalf);
  const BoxBoxResult r = collideBoxes(slab, cube);
  EXPECT_TRUE(allNear(r.manifold.normal, Vec3::UnitY(), 0.0));
  ASSERT_EQ(r.manifold.count, 4);
  for (double dx : {-0.5, 0.5}) {
    for (double dz : {-0.5, 0.5}) EXPECT_TRUE(boxHolds(r.manifold, Vec3(0.2 + dx, 0.495, -0.1 + dz))) << dx << dz;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.manifold.points[i].depth, 0.01, 1e-15);
}

TEST(CollideBoxes, CubeTurnedOnAnEqualCubeKeepsFourOfTheOctagon) {
  // The incident face, turned 45 degrees, clips to an octagon; four of its points remain.
  const OrientedBox a = makeOrientedBox(Vec3::Zero(), kHalf);
  const OrientedBox b = makeOrientedBox(Vec3(0, 0.99, 0), kHalf, rotationAbout(Vec3::UnitY(), M_PI / 4));
  const BoxBoxResult r = collideBoxes(a, b);
  EXPECT_TRUE(allNear(r.manifold.normal, Vec3::UnitY(), 1e-15));
  ASSERT_EQ(r.manifold.count, 4);
  for (int i = 0; i < 4; ++i) {
    const Vec3& p = r.manifold.points[i].position;
    EXPECT_NEAR(r.manifold.points[i].depth, 0.01, 1e-12);
    EXPECT_NEAR(p.y(), 0.495, 1e-12);
    EXPECT_LE(std::max(std::abs(p.x()), std::abs(p.z())), 0.5 + 1e-12);          // in A's square
    EXPECT_LE(std::abs(p.x()) + std::abs(p.z()), std::sqrt(0.5) + 1e-12);         // in B's diamond
  }
}

TEST(CollideBoxes, EdgeOnEdgeCrossingBoxesGiveOnePoint) {
  // A rolled 45 degrees about x has its top edge along x at y = sqrt(2)/2; B rolled 45 degrees
  // about z has its bottom edge along z. Lowered to overlap by 1 cm, the edges cross at x = z = 0.
  const double delta = 0.01, h = std::sqrt(0.5);
  const OrientedBox a = makeOrientedBox(Vec3::Zero(), kHalf, rotationAbout(Vec3::UnitX(), M_PI / 4));
  const OrientedBox b = makeOrientedBox(Vec3(0, 2 * h - delta, 0), kHalf, rotationAbout(Vec3::UnitZ(), M_PI / 4));
  const BoxBoxResult r = collideBoxes(a, b);
  EXPECT_EQ(r.axis, SatAxisKind::EdgeEdge);
  EXPECT_TRUE(allNear(r.manifold.normal, Vec3::UnitY(), 1e-12));
  ASSERT_EQ(r.manifold.count, 1);
  EXPECT_TRUE(allNear(r.manifold.points[0].position, Vec3(0, h - delta / 2, 0), 1e-12));
  EXPECT_NEAR(r.manifold.points[0].depth, delta, 1e-12);
}

TEST(CollideBoxes, SpeculativeMarginGivesNegativeDepths) {
  const OrientedBox a = makeOrientedBox(Vec3::Zero(), kHalf), b = makeOrientedBox(Vec3(1.05, 0, 0), kHalf);
  BoxBoxResult r = collideBoxes(a, b, 0.1);
  ASSERT_EQ(r.manifold.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(r.manifold.points[i].depth, -0.05, 1e-15);
    EXPECT_NEAR(r.manifold.points[i].position.x(), 0.525, 1e-15);
  }
  EXPECT_EQ(collideBoxes(a, b, 0.01).manifold.count, 0);
  EXPECT_EQ(collideBoxes(a, b).manifold.count, 0);
}

TEST(CollideBoxes, NearlyAlignedBoxesPreferTheFaceAxis) {
  // A tiny tilt makes an edge axis marginally better; the face axis still wins.
  const OrientedBox a = makeOrientedBox(Vec3::Zero(), kHalf);
  const OrientedBox b = makeOrientedBox(Vec3(0, 0.99, 0), kHalf, rotationAbout(Vec3(1, 0, 1), 1e-4));
  const BoxBoxResult r = collideBoxes(a, b);
  EXPECT_NE(r.axis, SatAxisKind::EdgeEdge);
  EXPECT_EQ(r.manifold.count, 4);
}

TEST(OrientedBoxOf, RecognisesBoxMeshesOnly) {
  const Mat3 R = rotationAbout(Vec3(1, 2, 3), 0.7);
  Mesh box = makeBox(Vec3(1, 2, 3));
  translateMesh(box, Vec3(0.1, 0, 0));  // vertices move by -0.1 in x
  const std::optional<OrientedBox> ob = orientedBoxOf(box, Vec3(5, 6, 7), R);
  ASSERT_TRUE(ob.has_value());
  EXPECT_TRUE(allNear(ob->halfExtents, Vec3(0.5, 1, 1.5), 1e-15));
  EXPECT_TRUE(allNear(ob->centre, R * Vec3(-0.1, 0, 0) + Vec3(5, 6, 7), 1e-15));
  EXPECT_TRUE(allNear(ob->rotation, R, 0.0));

  Mesh notBox = box;
  notBox.vertices[6] = Vec3(0.2, 0.3, 0.4);
  EXPECT_FALSE(orientedBoxOf(notBox, Vec3::Zero(), Mat3::Identity()).has_value());
  Mesh tetra;
  tetra.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  EXPECT_FALSE(orientedBoxOf(tetra, Vec3::Zero(), Mat3::Identity()).has_value());
}

// Every contact point of random overlapping boxes lies midway between the surfaces: point +
// n depth / 2 on A's surface and point - n depth / 2 on B's; no depth exceeds the axis depth.
TEST(CollideBoxes, RandomPairsPutEveryPointBetweenTheTwoSurfaces) {
  std::mt19937 rng(413);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.1, 1.0), reach(0.0, 1.5);
  int overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const OrientedBox a = makeOrientedBox(Vec3::Zero(), Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    const OrientedBox b = makeOrientedBox(Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng),
                                          Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    const BoxBoxResult r = collideBoxes(a, b);
    const double sat = test::satSeparation(a, b);
    ASSERT_EQ(r.manifold.count > 0, sat <= 0.0) << "trial " << trial;
    if (r.manifold.count == 0) continue;
    ++overlapping;
    const Vec3& n = r.manifold.normal;
    ASSERT_NEAR(n.norm(), 1.0, 1e-12);
    ASSERT_GE(n.dot(b.centre - a.centre), 0.0) << "trial " << trial;
    // The chosen axis is never much worse than the best one (the face preference).
    ASSERT_GE(r.separation, sat / ((1 - kSatEdgeRelTolerance) * (1 - kSatFaceRelTolerance)) - 3 * kSatEdgeAbsTolerance) << "trial " << trial;
    for (int i = 0; i < r.manifold.count; ++i) {
      const ContactPoint& c = r.manifold.points[i];
      ASSERT_NEAR(test::boxSignedDistance(a, c.position + n * (0.5 * c.depth)), 0.0, 1e-9) << "trial " << trial;
      ASSERT_NEAR(test::boxSignedDistance(b, c.position - n * (0.5 * c.depth)), 0.0, 1e-9) << "trial " << trial;
      ASSERT_LE(c.depth, -r.separation + 1e-9) << "trial " << trial;
      ASSERT_GE(c.depth, -1e-9) << "trial " << trial;
    }
  }
  EXPECT_GT(overlapping, 800);
}

}  // namespace
}  // namespace rbsim
