// geometry/triangle_bvh: closest points on a triangle against brute-force minimisation, and the
// hierarchy's nearest, within-radius and segment answers against testing every triangle.
#include "geometry/triangle_bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "geometry/distance.h"
#include "rbsim/geometry/mesh_generators.h"

namespace rbsim {
namespace {

Vec3 randomBvhPoint(std::mt19937& rng, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  return {u(rng), u(rng), u(rng)};
}

// Brute force: the distance is convex over the triangle, so the best of a fine barycentric grid
// is within the grid spacing of the minimum.
constexpr int kBruteSteps = 300;
double bruteDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kBruteSteps; ++i) {
    for (int j = 0; i + j <= kBruteSteps; ++j) {
      const double u = double(i) / kBruteSteps, v = double(j) / kBruteSteps;
      best = std::min(best, (p - ((1 - u - v) * a + u * b + v * c)).norm());
    }
  }
  return best;
}

TEST(ClosestPointOnTriangle, MatchesBruteForceMinimisationInAllSevenRegions) {
  const Vec3 a(0.1, -0.2, 0.0), b(1.0, 0.1, 0.2), c(0.3, 0.9, -0.1);
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  // The grid's points are within longest / kBruteSteps of every triangle point.
  const double gridBound = longest / kBruteSteps;
  std::mt19937 rng(11);
  std::set<TriangleFeature> regions;
  for (int n = 0; n < 400; ++n) {
    const Vec3 p = Vec3(0.45, 0.25, 0.0) + randomBvhPoint(rng, 1.5);
    const PointTriangleResult r = closestPointOnTriangle(p, a, b, c);
    regions.insert(r.feature);
    const double brute = bruteDistance(p, a, b, c);
    EXPECT_LE(r.distance, brute + 1e-12) << "never farther than a point of the triangle";
    EXPECT_GE(r.distance, brute - gridBound) << p.transpose();
    EXPECT_NEAR((p - r.closest).norm(), r.distance, 1e-12);
  }
  EXPECT_EQ(regions.size(), 7u) << "every vertex, edge and the face region was exercised";
}

class TriangleBvhOnATorus : public ::testing::Test {
 protected:
  Mesh mesh = makeTorus(1.0, 0.3, 24, 12);
  TriangleBvh bvh{mesh};

  SurfacePoint bruteNearest(const Vec3& p) const {
    SurfacePoint best;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const Triangle& tri = mesh.triangles[t];
      const PointTriangleResult r = closestPointOnTriangle(p, mesh.vertices[tri[0]],
                                                           mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
      if (r.distance < best.distance) best = {r.closest, r.distance, t};
    }
    return best;
  }
};

TEST_F(TriangleBvhOnATorus, NearestMatchesTestingEveryTriangle) {
  EXPECT_EQ(bvh.triangleCount(), mesh.triangles.size());
  std::mt19937 rng(12);
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p = randomBvhPoint(rng, 2.0);
    const SurfacePoint fast = bvh.nearest(p), brute = bruteNearest(p);
    EXPECT_NEAR(fast.distance, brute.distance, 1e-14) << p.transpose();
    EXPECT_NEAR((fast.point - p).norm(), fast.distance, 1e-12);
  }
}

TEST_F(TriangleBvhOnATorus, ClosestWithinARadiusAnswersExactlyWhenSomethingIsThatNear) {
  std::mt19937 rng(13);
  int found = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p = randomBvhPoint(rng, 1.6);
    const double radius = 0.15;
    const auto hit = bvh.closestWithin(p, radius);
    const double brute = bruteNearest(p).distance;
    ASSERT_EQ(hit.has_value(), brute <= radius) << p.transpose();
    if (hit) {
      ++found;
      EXPECT_NEAR(hit->distance, brute, 1e-14);
    }
  }
  EXPECT_GT(found, 100) << "the sample must exercise both answers";
}

TEST_F(TriangleBvhOnATorus, SegmentCrossingsMatchTestingEveryTriangle) {
  std::mt19937 rng(14);
  int crossed = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 a = randomBvhPoint(rng, 1.4), b = a + randomBvhPoint(rng, 0.5);
    int brute = 0;
    for (const Triangle& tri : mesh.triangles) {
      double t = 0.0;
      brute += segmentCrossesTriangle(a, b, mesh.vertices[tri[0]], mesh.vertices[tri[1]],
                                      mesh.vertices[tri[2]], t);
    }
    EXPECT_EQ(bvh.crossings(a, b).count, brute);
    crossed += brute > 0;
  }
  EXPECT_GT(crossed, 100);
}

TEST(SegmentCrossesTriangle, CountsEdgesAndVerticesAndRejectsParallelAndShortSegments) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  double t = -1.0;
  EXPECT_TRUE(segmentCrossesTriangle(Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), a, b, c, t));
  EXPECT_NEAR(t, 0.5, 1e-15);
  EXPECT_TRUE(segmentCrossesTriangle(Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), a, b, c, t)) << "edge bc";
  EXPECT_TRUE(segmentCrossesTriangle(Vec3(0, 0, -1), Vec3(0, 0, 1), a, b, c, t)) << "vertex a";
  EXPECT_FALSE(segmentCrossesTriangle(Vec3(0.6, 0.6, -1), Vec3(0.6, 0.6, 1), a, b, c, t));
  EXPECT_FALSE(segmentCrossesTriangle(Vec3(0.2, 0.2, 0.1), Vec3(0.2, 0.2, 1), a, b, c, t)) << "short";
  EXPECT_FALSE(segmentCrossesTriangle(Vec3(-1, 0.2, 0), Vec3(1, 0.2, 0), a, b, c, t)) << "in plane";
}


TEST(SelfCrossing, FindsTwoInterpenetratingBoxesAndNothingInAValidMesh) {
  EXPECT_FALSE(TriangleBvh(makeTorus(1.0, 0.3, 48, 24)).selfCrossing(1e7).found);
  EXPECT_FALSE(TriangleBvh(makeBox(Vec3::Ones())).selfCrossing(1e7).found);
  Mesh two = makeBox(Vec3::Ones());
  const auto shift = static_cast<std::uint32_t>(two.vertices.size());
  for (const Vec3& p : makeBox(Vec3::Ones()).vertices) two.vertices.push_back(p + Vec3(0.5, 0.25, 0.125));
  for (Triangle t : makeBox(Vec3::Ones()).triangles) two.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  const SelfCrossing crossing = TriangleBvh(two).selfCrossing(1e7);
  ASSERT_TRUE(crossing.found);
  EXPECT_LT(crossing.first, 12u);
  EXPECT_GE(crossing.second, 12u);
  EXPECT_TRUE((crossing.point.array() >= -0.5 - 1e-12).all() && (crossing.point.array() <= 0.5 + 1e-12).all());
  const SelfCrossing tooFew = TriangleBvh(two).selfCrossing(1.0);
  EXPECT_TRUE(tooFew.exhausted);
  EXPECT_FALSE(tooFew.found);
}

TEST(SelfCrossing, TouchingIsNotCrossingButAFoldThroughASharedCornerIs) {
  const Vec3 t[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  Vec3 point;
  const Vec3 touching[3] = {{0.2, 0.2, 0}, {0.2, 0.2, 1}, {1, 1, 1}};  // a corner on t
  EXPECT_FALSE(trianglesCross(t, touching, point));
  const Vec3 piercing[3] = {{0.2, 0.2, -1}, {0.2, 0.2, 1}, {1, 1, 1}};
  ASSERT_TRUE(trianglesCross(t, piercing, point));
  EXPECT_TRUE(point.isApprox(Vec3(0.2, 0.2, 0)));
  const Vec3 fold[3] = {{0, 0, 0}, {0.5, 0.1, 1}, {0.1, 0.5, -1}};  // shares corner 0, cuts through t
  EXPECT_TRUE(trianglesCross(t, fold, point));
}

}  // namespace
}  // namespace rbsim
