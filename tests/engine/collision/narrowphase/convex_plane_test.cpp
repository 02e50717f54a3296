// collision/narrowphase/convex_plane: a box on the ground flat (4 points), tilted onto an edge (2)
// and onto a corner (1), speculative contacts, a tilted plane, and reduction of many points.
#include "collision/narrowphase/convex_plane.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "narrowphase_test_util.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxCorners;
using test::makeOrientedBox;
using test::rotationAbout;

const Plane kGround{Vec3::UnitY(), 0.0};

bool planeHolds(const ContactManifold& m, const Vec3& p, double tol = 1e-12) {
  for (int i = 0; i < m.count; ++i) {
    if ((m.points[i].position - p).norm() <= tol) return true;
  }
  return false;
}

TEST(CollidePlaneConvex, FlatBoxSunkOneCentimetreHasFourCorners) {
  const ContactManifold m = collidePlaneConvex(kGround, boxCorners(makeOrientedBox(Vec3(0, 0.49, 0), Vec3(1, 0.5, 2))));
  EXPECT_TRUE(allNear(m.normal, Vec3::UnitY(), 0.0));  // plane = A, body = B
  ASSERT_EQ(m.count, 4);
  for (double x : {-1.0, 1.0}) {
    for (double z : {-2.0, 2.0}) EXPECT_TRUE(planeHolds(m, Vec3(x, -0.005, z))) << x << " " << z;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.points[i].depth, 0.01, 1e-15);
}

TEST(CollidePlaneConvex, BoxTiltedOntoAnEdgeHasTwoPoints) {
  // Rolled 30 degrees about z, the unit cube's lowest edge runs along z.
  const Mat3 R = rotationAbout(Vec3::UnitZ(), M_PI / 6);
  const double reach = 0.5 * (std::cos(M_PI / 6) + std::sin(M_PI / 6));  // centre to lowest edge in y
  const double depth = 0.02;
  const OrientedBox box = makeOrientedBox(Vec3(0.3, reach - depth, 0), Vec3::Constant(0.5), R);
  const ContactManifold m = collidePlaneConvex(kGround, boxCorners(box));
  ASSERT_EQ(m.count, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].depth, depth, 1e-12);
    EXPECT_NEAR(m.points[i].position.y(), -depth / 2, 1e-12);
    EXPECT_NEAR(std::abs(m.points[i].position.z()), 0.5, 1e-12);
  }
}

TEST(CollidePlaneConvex, BoxTiltedOntoACornerHasOnePoint) {
  const Mat3 R = rotationAbout(Vec3::UnitX(), 0.35) * rotationAbout(Vec3::UnitZ(), M_PI / 6);
  OrientedBox box = makeOrientedBox(Vec3::Zero(), Vec3::Constant(0.5), R);
  double lowest = 1e9;
  Vec3 corner;
  for (const Vec3& p : boxCorners(box)) {
    if (p.y() < lowest) {
      lowest = p.y();
      corner = p;
    }
  }
  box.centre.y() = -lowest - 0.03;  // the lowest corner 3 cm below the ground
  corner.y() = -0.03;
  const ContactManifold m = collidePlaneConvex(kGround, boxCorners(box));
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].depth, 0.03, 1e-12);
  EXPECT_TRUE(allNear(m.points[0].position, corner + Vec3(0, 0.015, 0), 1e-12));
}

TEST(CollidePlaneConvex, MarginGivesSpeculativeContactsAbove) {
  const std::vector<Vec3> box = boxCorners(makeOrientedBox(Vec3(0, 0.505, 0), Vec3::Constant(0.5)));
  ContactManifold m = collidePlaneConvex(kGround, box, 0.01);
  ASSERT_EQ(m.count, 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.points[i].depth, -0.005, 1e-15);
  EXPECT_EQ(collidePlaneConvex(kGround, box, 0.001).count, 0);
  EXPECT_EQ(collidePlaneConvex(kGround, box).count, 0);
}

TEST(CollidePlaneConvex, TiltedPlaneUsesItsOwnNormal) {
  const Vec3 n = Vec3(1, 1, 0).normalized();
  const Plane plane{n, 2.0};
  const std::vector<Vec3> pts = {n * 1.9 + Vec3(0, 0, 1), n * 1.95 + Vec3(1, -1, 0), n * 3.0};
  const ContactManifold m = collidePlaneConvex(plane, pts);
  EXPECT_TRUE(allNear(m.normal, n, 0.0));
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR(m.points[0].depth, 0.1, 1e-12);  // the deepest first
  EXPECT_NEAR(m.points[1].depth, 0.05, 1e-12);
  EXPECT_NEAR(plane.signedDistance(m.points[0].position), -0.05, 1e-12);  // midway
}

TEST(CollidePlaneConvex, ManyPointsReduceToFourSpanningTheFootprint) {
  // A 32-sided prism standing on the ground, tipped a little so rim point 5 is the deepest.
  std::vector<Vec3> prism;
  const double deepest = 2 * M_PI * 5 / 32;
  for (int k = 0; k < 32; ++k) {
    const double a = 2 * M_PI * k / 32;
    prism.emplace_back(std::cos(a), -0.01 - 0.001 * std::cos(a - deepest), std::sin(a));
    prism.emplace_back(std::cos(a), 1.0, std::sin(a));
  }
  const ContactManifold m = collidePlaneConvex(kGround, prism);
  ASSERT_EQ(m.count, 4);
  EXPECT_NEAR(m.points[0].depth, 0.011, 1e-12);
  EXPECT_NEAR(m.points[0].position.x(), std::cos(deepest), 1e-12);
  // The kept quadrilateral covers most of the disc (the inscribed square is 2 / pi of it).
  Vec3 c = Vec3::Zero();
  std::vector<Vec3> ring;
  for (int i = 0; i < 4; ++i) {
    ring.push_back(m.points[i].position);
    c += m.points[i].position / 4.0;
  }
  std::sort(ring.begin(), ring.end(), [&](const Vec3& p, const Vec3& q) {
    return std::atan2(p.z() - c.z(), p.x() - c.x()) < std::atan2(q.z() - c.z(), q.x() - c.x());
  });
  double area = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Vec3& p = ring[i];
    const Vec3& q = ring[(i + 1) % 4];
    area += 0.5 * (p.x() * q.z() - q.x() * p.z());
  }
  EXPECT_GT(area, 0.6 * M_PI);
}

// A mesh from an implicit surface rests on a flat disc bevelled half a grid cell up at its rim
// (marching tetrahedra chamfer the edge): the bevel ring reaches farther out than the floor but
// hangs 9 mm above it. Reduction by area alone takes the bevel: one point planeHolds the body and it
// rocks. With the body's reach as the slab, only vertices that could reach the deepest depth in
// the step are candidates: at rest the four points are the floor's; a body rolling onto the
// bevel keeps the bevel.
TEST(CollidePlaneConvex, ARestingFaceIsHeldByItsFloorNotByABevelAboveIt) {
  std::vector<Vec3> disc;
  constexpr int kRim = 64;
  for (int i = 0; i < kRim; ++i) {
    const double a = 2.0 * M_PI * i / kRim;
    disc.emplace_back(0.47 * std::cos(a), -0.001 + 1e-5 * std::sin(3.0 * a), 0.47 * std::sin(a));  // floor, 1 mm deep
    disc.emplace_back(0.49 * std::cos(a), 0.008, 0.49 * std::sin(a));                            // bevel, 8 mm up
  }
  const double margin = 0.02;
  const ContactManifold byArea = collidePlaneConvex(kGround, disc, margin);
  int below = 0;
  for (int k = 0; k < byArea.count; ++k) below += byArea.points[k].depth > 0.0 ? 1 : 0;
  EXPECT_EQ(below, 1) << "without the body's motion the bevel is chosen (the case this guards against)";

  // At rest at dt = 1/60 s the body's reach is g dt^2 = 2.7 mm; with 1 mm of slack the slab is
  // below the bevel's 9 mm.
  const double restSlab = 1e-3 + 9.81 / 3600.0;
  const ContactManifold held = collidePlaneConvex(kGround, disc, margin, restSlab);
  ASSERT_EQ(held.count, 4);
  for (int k = 0; k < held.count; ++k) {
    EXPECT_GT(held.points[k].depth, 0.0);
    EXPECT_NEAR(std::hypot(held.points[k].position.x(), held.points[k].position.z()), 0.47, 1e-9);
  }
  // Rolling at 2 rad/s, its rim moves 0.49 * 2 / 60 = 16 mm in the step: the bevel is within reach.
  const ContactManifold rolled = collidePlaneConvex(kGround, disc, margin, restSlab + 0.49 * 2.0 / 60.0);
  bool bevelKept = false;
  for (int k = 0; k < rolled.count; ++k) bevelKept = bevelKept || rolled.points[k].depth < 0.0;
  EXPECT_TRUE(bevelKept);
}

}  // namespace
}  // namespace rbsim
