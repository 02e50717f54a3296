// collision/narrowphase/gjk: distances and overlap of convex vertex sets, on boxes with known
// answers, degenerate sets, and random sets against a brute-force feature-pair minimum.
#include "collision/narrowphase/gjk.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "geometry/distance.h"
#include "narrowphase_test_util.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using test::boxCorners;
using test::makeOrientedBox;

std::vector<Vec3> cube(const Vec3& centre, const Mat3& R = Mat3::Identity()) {
  return boxCorners(makeOrientedBox(centre, Vec3::Constant(0.5), R));
}

bool hasNaN(const GjkResult& r) {
  return std::isnan(r.distance) || r.pointA.hasNaN() || r.pointB.hasNaN();
}

TEST(Gjk, SupportIsTheVertexFurthestAlongTheDirection) {
  const std::vector<Vec3> c = cube(Vec3::Zero());
  EXPECT_TRUE(allNear(c[supportIndex(c, Vec3(1, 2, 3))], Vec3(0.5, 0.5, 0.5), 0.0));
  EXPECT_TRUE(allNear(c[supportIndex(c, Vec3(-1, 2, -3))], Vec3(-0.5, 0.5, -0.5), 0.0));
  const SupportPoint s = minkowskiSupport(c, cube(Vec3(3, 0, 0)), Vec3(1, 0, 0));
  EXPECT_NEAR(s.w.x(), 0.5 - 2.5, 1e-15);
}

TEST(Gjk, UnitCubesAtAKnownFaceSeparation) {
  const GjkResult r = gjk(cube(Vec3::Zero()), cube(Vec3(1.5, 0.2, -0.1)));
  EXPECT_FALSE(r.overlap);
  EXPECT_NEAR(r.distance, 0.5, 1e-12);
  EXPECT_NEAR(r.pointA.x(), 0.5, 1e-12);
  EXPECT_NEAR(r.pointB.x(), 1.0, 1e-12);
  EXPECT_NEAR((r.pointB - r.pointA).norm(), 0.5, 1e-12);
  EXPECT_LT(r.iterations, kGjkMaxIterations);
}

TEST(Gjk, UnitCubesCornerToCorner) {
  const GjkResult r = gjk(cube(Vec3::Zero()), cube(Vec3(2, 2, 2)));
  EXPECT_NEAR(r.distance, std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(allNear(r.pointA, Vec3::Constant(0.5), 1e-12));
  EXPECT_TRUE(allNear(r.pointB, Vec3::Constant(1.5), 1e-12));
}

TEST(Gjk, OverlappingAndTouchingCubes) {
  GjkResult r = gjk(cube(Vec3::Zero()), cube(Vec3(0.9, 0.3, 0)));
  EXPECT_TRUE(r.overlap);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_GE(r.simplex.size, 1);
  r = gjk(cube(Vec3::Zero()), cube(Vec3::Zero()));  // coincident
  EXPECT_TRUE(r.overlap);
  r = gjk(cube(Vec3::Zero()), cube(Vec3(1, 0, 0)));  // face to face, touching
  EXPECT_TRUE(r.overlap);
  r = gjk(cube(Vec3::Zero()), cube(Vec3(1, 1, 1)));  // corner to corner, touching
  EXPECT_TRUE(r.overlap);
  r = gjk(cube(Vec3::Zero()), cube(Vec3(1 + 1e-6, 0, 0)));
  EXPECT_FALSE(r.overlap);
  EXPECT_NEAR(r.distance, 1e-6, 1e-12);
}

TEST(Gjk, DegenerateSetsGiveNoNaN) {
  // A flat square (coplanar points), repeated vertices, a segment and a single point.
  const std::vector<Vec3> square = {Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(1, 0, 1), Vec3(-1, 0, 1), Vec3(1, 0, 1)};
  const std::vector<Vec3> point = {Vec3(0.3, 2, 0.2)};
  GjkResult r = gjk(square, point);
  EXPECT_FALSE(hasNaN(r));
  EXPECT_NEAR(r.distance, 2.0, 1e-12);
  EXPECT_TRUE(allNear(r.pointA, Vec3(0.3, 0, 0.2), 1e-12));
  const std::vector<Vec3> segment = {Vec3(-5, -1, 0.5), Vec3(5, 1, 0.5), Vec3(5, 1, 0.5)};
  r = gjk(square, segment);  // crosses the square
  EXPECT_TRUE(r.overlap);
  EXPECT_FALSE(hasNaN(r));
  const std::vector<Vec3> seg1 = {Vec3(-1, 0, 0), Vec3(1, 0, 0)}, seg2 = {Vec3(0.5, -1, 2), Vec3(0.5, 1, 2)};
  r = gjk(seg1, seg2);
  EXPECT_NEAR(r.distance, 2.0, 1e-12);
  EXPECT_TRUE(allNear(r.pointA, Vec3(0.5, 0, 0), 1e-12));
  const std::vector<Vec3> same = {Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)};
  r = gjk(same, point);
  EXPECT_NEAR(r.distance, (Vec3(1, 1, 1) - point[0]).norm(), 1e-12);
  EXPECT_TRUE(std::isinf(gjk({}, point).distance));
}

// Brute force: the hulls' distance is attained by a vertex-face or an edge-edge pair. Taking
// every triple of points as a "face" and every pair as an "edge" is a superset of the hull
// features, all inside the hulls, so the minimum over it is the distance exactly.
double bruteForceDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double best = std::numeric_limits<double>::infinity();
  const auto vertexFace = [&](const std::vector<Vec3>& p, const std::vector<Vec3>& t) {
    for (std::size_t i = 0; i < t.size(); ++i)
      for (std::size_t j = i + 1; j < t.size(); ++j)
        for (std::size_t k = j + 1; k < t.size(); ++k)
          for (const Vec3& v : p) best = std::min(best, closestPointOnTriangle(v, t[i], t[j], t[k]).distance);
  };
  vertexFace(a, b);
  vertexFace(b, a);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      for (std::size_t k = 0; k < b.size(); ++k)
        for (std::size_t l = k + 1; l < b.size(); ++l)
          best = std::min(best, closestPointsSegmentSegment(a[i], a[j], b[k], b[l]).distance);
  return best;
}

// Checks one GJK answer with certificates: when apart, the plane through the closest points
// separates the sets and the distance matches the brute force; when overlapping, the returned
// points (convex combinations of each set's vertices) coincide.
void checkAgainstBruteForce(const std::vector<Vec3>& a, const std::vector<Vec3>& b, int trial, int& apart) {
  const GjkResult r = gjk(a, b);
  ASSERT_FALSE(hasNaN(r)) << "trial " << trial;
  ASSERT_LT(r.iterations, kGjkMaxIterations) << "trial " << trial;
  if (r.overlap) {
    ASSERT_LE((r.pointA - r.pointB).norm(), 1e-9) << "trial " << trial;
    return;
  }
  ++apart;
  ASSERT_NEAR(r.distance, bruteForceDistance(a, b), 1e-9) << "trial " << trial;
  const Vec3 n = (r.pointB - r.pointA) / r.distance;
  for (const Vec3& p : a) ASSERT_LE(n.dot(p - r.pointA), 1e-9) << "trial " << trial;
  for (const Vec3& p : b) ASSERT_GE(n.dot(p - r.pointB), -1e-9) << "trial " << trial;
}

TEST(Gjk, RandomPointSetsMatchTheBruteForceDistance) {
  std::mt19937 rng(409);
  std::uniform_real_distribution<double> u(-1.0, 1.0), far(0.0, 3.0);
  int apart = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int na = 4 + trial % 5, nb = 4 + (trial / 5) % 5;
    std::vector<Vec3> a, b;
    const Vec3 offset = Vec3(u(rng), u(rng), u(rng)).normalized() * far(rng);
    for (int i = 0; i < na; ++i) a.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < nb; ++i) b.push_back(Vec3(u(rng), u(rng), u(rng)) * 0.7 + offset);
    checkAgainstBruteForce(a, b, trial, apart);
  }
  EXPECT_GT(apart, 400);
  EXPECT_LT(apart, 1900);
}

TEST(Gjk, RandomBoxPairsMatchTheBruteForceDistance) {
  std::mt19937 rng(410);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.1, 1.0), far(0.5, 3.0);
  int apart = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const OrientedBox ba = makeOrientedBox(Vec3::Zero(), Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    const OrientedBox bb = makeOrientedBox(Vec3(u(rng), u(rng), u(rng)).normalized() * far(rng),
                                           Vec3(size(rng), size(rng), size(rng)), test::randomRotation(rng));
    checkAgainstBruteForce(boxCorners(ba), boxCorners(bb), trial, apart);
    // Overlap agrees with the exact 15-axis SAT.
    const bool satOverlap = test::satSeparation(ba, bb) <= 0.0;
    ASSERT_EQ(gjk(boxCorners(ba), boxCorners(bb)).overlap, satOverlap) << "trial " << trial;
  }
  EXPECT_GT(apart, 100);
}

}  // namespace
}  // namespace rbsim
