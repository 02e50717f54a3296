// collision/narrowphase/epa: penetration normal and depth from GJK's simplex: boxes with known
// answers, start simplices of 1 to 3 points, random boxes against the exact SAT depth, and random
// point sets against the support function (no direction separates with less translation).
#include "collision/narrowphase/epa.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "narrowphase_test_util.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxCorners;
using test::makeOrientedBox;

std::vector<Vec3> epaCube(const Vec3& centre, const Mat3& R = Mat3::Identity()) {
  return boxCorners(makeOrientedBox(centre, Vec3::Constant(0.5), R));
}

EpaResult penetration(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const GjkResult g = gjk(a, b);
  EXPECT_TRUE(g.overlap);
  return epa(a, b, g.simplex);
}

TEST(Epa, UnitCubesWithKnownNormalAndDepth) {
  EpaResult r = penetration(epaCube(Vec3::Zero()), epaCube(Vec3(0.9, 0.1, -0.2)));
  ASSERT_TRUE(r.valid);
  EXPECT_TRUE(allNear(r.normal, Vec3::UnitX(), 1e-9));
  EXPECT_NEAR(r.depth, 0.1, 1e-9);
  EXPECT_TRUE(allNear(r.pointA - r.pointB, r.depth * r.normal, 1e-9));
  EXPECT_NEAR(r.pointA.x(), 0.5, 1e-9);  // A's face, inside B
  EXPECT_NEAR(r.pointB.x(), 0.4, 1e-9);  // B's face, inside A
  r = penetration(epaCube(Vec3::Zero()), epaCube(Vec3(0.2, -0.7, 0.1)));
  EXPECT_TRUE(allNear(r.normal, -Vec3::UnitY(), 1e-9));
  EXPECT_NEAR(r.depth, 0.3, 1e-9);
}

TEST(Epa, TouchingCubesHaveZeroDepth) {
  const EpaResult r = penetration(epaCube(Vec3::Zero()), epaCube(Vec3(1, 0.3, 0)));
  ASSERT_TRUE(r.valid);
  EXPECT_NEAR(r.depth, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(r.normal.x()), 1.0, 1e-9);
}

TEST(Epa, CoincidentCubesNeedAFullFaceWidth) {
  const EpaResult r = penetration(epaCube(Vec3::Zero()), epaCube(Vec3::Zero()));
  ASSERT_TRUE(r.valid);
  EXPECT_NEAR(r.depth, 1.0, 1e-9);
  EXPECT_NEAR(r.normal.cwiseAbs().maxCoeff(), 1.0, 1e-9);
}

TEST(Epa, BlowsUpStartSimplicesOfOneTwoAndThreePoints) {
  const std::vector<Vec3> a = epaCube(Vec3::Zero()), b = epaCube(Vec3(0.9, 0, 0));
  // Points of A - B built from points inside both boxes; the origin is in each simplex's hull.
  GjkSimplex s;
  s.size = 1;
  s.points[0] = {Vec3::Zero(), Vec3(0.45, 0, 0), Vec3(0.45, 0, 0)};
  const auto expectKnown = [&](const GjkSimplex& start) {
    const EpaResult r = epa(a, b, start);
    ASSERT_TRUE(r.valid) << start.size;
    EXPECT_TRUE(allNear(r.normal, Vec3::UnitX(), 1e-9)) << start.size;
    EXPECT_NEAR(r.depth, 0.1, 1e-9) << start.size;
  };
  expectKnown(s);
  s.size = 2;
  s.points[0] = {Vec3(0.05, 0, 0), Vec3(0.5, 0, 0), Vec3(0.45, 0, 0)};
  s.points[1] = {Vec3(-0.05, 0, 0), Vec3(0.45, 0, 0), Vec3(0.5, 0, 0)};
  expectKnown(s);
  s.size = 3;
  s.points[0] = {Vec3(0.05, 0.1, 0), Vec3(0.5, 0.1, 0), Vec3(0.45, 0, 0)};
  s.points[1] = {Vec3(-0.05, 0.1, 0), Vec3(0.45, 0.1, 0), Vec3(0.5, 0, 0)};
  s.points[2] = {Vec3(0, -0.2, 0), Vec3(0.45, -0.2, 0), Vec3(0.45, 0, 0)};
  expectKnown(s);
  // A duplicated point is a smaller simplex in disguise.
  s.points[2] = s.points[1];
  expectKnown(s);
}

TEST(Epa, FlatMinkowskiDifferenceIsReportedInvalid) {
  // Two squares in the plane y = 0: A - B is flat, no tetrahedron fits.
  const std::vector<Vec3> a = {Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(1, 0, 1), Vec3(-1, 0, 1)};
  const std::vector<Vec3> b = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 2), Vec3(0, 0, 2)};
  const GjkResult g = gjk(a, b);
  ASSERT_TRUE(g.overlap);
  EXPECT_FALSE(epa(a, b, g.simplex).valid);
}

TEST(Epa, RandomBoxPairsMatchTheExactSatDepth) {
  std::mt19937 rng(411);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.1, 1.0), reach(0.0, 1.2);
  int tested = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const OrientedBox ba = makeOrientedBox(Vec3::Zero(), Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    const OrientedBox bb = makeOrientedBox(Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng),
                                           Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    Vec3 satAxis;
    const double sat = test::satSeparation(ba, bb, &satAxis);
    if (sat > -1e-6) continue;  // apart or barely touching
    ++tested;
    const std::vector<Vec3> a = boxCorners(ba), b = boxCorners(bb);
    const GjkResult g = gjk(a, b);
    ASSERT_TRUE(g.overlap) << "trial " << trial;
    const EpaResult r = epa(a, b, g.simplex);
    ASSERT_TRUE(r.valid) << "trial " << trial;
    ASSERT_TRUE(r.converged) << "trial " << trial;
    ASSERT_NEAR(r.depth, -sat, 1e-8) << "trial " << trial;
    ASSERT_NEAR(r.normal.norm(), 1.0, 1e-12);
    ASSERT_TRUE(allNear(r.pointA - r.pointB, r.depth * r.normal, 1e-8)) << "trial " << trial;
    // Moving B by depth + 1 um along the normal separates the boxes by about 1 um.
    const OrientedBox moved = makeOrientedBox(bb.centre + r.normal * (r.depth + 1e-6), bb.halfExtents, bb.rotation);
    ASSERT_NEAR(gjk(a, boxCorners(moved)).distance, 1e-6, 1e-8) << "trial " << trial;
  }
  EXPECT_GT(tested, 400);
}

// Boxes sharing their orientation, or one axis, make A - B full of coplanar and collinear
// support points: new points on the line of a horizon edge, faces coplanar with the new point.
TEST(Epa, AlignedAndCoaxialBoxPairsStillMatchTheSatDepth) {
  std::mt19937 rng(416);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.1, 1.0), reach(0.0, 1.2);
  int tested = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Mat3 Ra = test::randomRotation(rng);
    const Mat3 Rb = trial % 2 == 0 ? Mat3(Ra * test::rotationAbout(Vec3::Unit(trial % 3), M_PI / 2 * (trial % 4)))
                                   : Mat3(Ra * test::rotationAbout(Vec3::Unit(trial % 3), u(rng)));
    const OrientedBox ba = makeOrientedBox(Vec3::Zero(), Vec3(size(rng), size(rng), size(rng)), Ra);
    const OrientedBox bb = makeOrientedBox(Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng),
                                           Vec3(size(rng), size(rng), size(rng)), Rb);
    const double sat = test::satSeparation(ba, bb);
    if (sat > -1e-6) continue;
    ++tested;
    const std::vector<Vec3> a = boxCorners(ba), b = boxCorners(bb);
    const GjkResult g = gjk(a, b);
    ASSERT_TRUE(g.overlap) << "trial " << trial;
    const EpaResult r = epa(a, b, g.simplex);
    ASSERT_TRUE(r.valid && r.converged) << "trial " << trial;
    ASSERT_NEAR(r.depth, -sat, 1e-8) << "trial " << trial;
  }
  EXPECT_GT(tested, 800);
}

// h(u) = max over a, b of u . (a - b): the translation of B along u that just separates the sets.
double supportOfDifference(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& u) {
  return u.dot(a[supportIndex(a, u)]) - u.dot(b[supportIndex(b, -u)]);
}

TEST(Epa, RandomPointSetsNoDirectionSeparatesWithLessTranslation) {
  std::mt19937 rng(412);
  std::uniform_real_distribution<double> u(-1.0, 1.0), reach(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  int tested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Vec3> a, b;
    const Vec3 offset = Vec3(u(rng), u(rng), u(rng)).normalized() * reach(rng);
    for (int i = 0; i < 8; ++i) a.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < 8; ++i) b.push_back(Vec3(u(rng), u(rng), u(rng)) + offset);
    const GjkResult gr = gjk(a, b);
    if (!gr.overlap) continue;
    ++tested;
    const EpaResult r = epa(a, b, gr.simplex);
    ASSERT_TRUE(r.valid && r.converged) << "trial " << trial;
    ASSERT_NEAR(supportOfDifference(a, b, r.normal), r.depth, 1e-8) << "trial " << trial;
    for (int k = 0; k < 2000; ++k) {
      const Vec3 dir = Vec3(g(rng), g(rng), g(rng)).normalized();
      ASSERT_GE(supportOfDifference(a, b, dir), r.depth - 1e-8) << "trial " << trial << " dir " << dir.transpose();
    }
    std::vector<Vec3> moved = b;
    for (Vec3& p : moved) p += r.normal * (r.depth + 1e-6);
    ASSERT_FALSE(gjk(a, moved).overlap) << "trial " << trial;
    moved = b;
    for (Vec3& p : moved) p += r.normal * (r.depth - 1e-6);
    ASSERT_TRUE(gjk(a, moved).overlap) << "trial " << trial;
  }
  EXPECT_GT(tested, 100);
}

}  // namespace
}  // namespace rbsim
