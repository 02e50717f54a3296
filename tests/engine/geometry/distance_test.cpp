// geometry/distance: seed 004's point-point, point-edge and point-face distances and
// segment-segment closest points, on hand-made cases and against independent references.
#include "geometry/distance.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0);

TEST(PointPointDistance, IsTheEuclideanNorm) {
  EXPECT_DOUBLE_EQ(pointPointDistance(Vec3(1, 2, 3), Vec3(4, 6, 3)), 5.0);
  EXPECT_DOUBLE_EQ(pointPointDistance(Vec3(1, 2, 3), Vec3(1, 2, 3)), 0.0);
}

TEST(ClosestPointOnSegment, InteriorAndBothEndRegions) {
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  PointSegmentResult r = closestPointOnSegment(Vec3(0.5, 3, 4), a, b);
  EXPECT_EQ(r.feature, SegmentFeature::Interior);
  EXPECT_TRUE(allNear(r.closest, Vec3(0.5, 0, 0), 1e-15));
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
  EXPECT_DOUBLE_EQ(r.t, 0.25);
  r = closestPointOnSegment(Vec3(-1, 1, 0), a, b);
  EXPECT_EQ(r.feature, SegmentFeature::Start);
  EXPECT_DOUBLE_EQ(r.distance, std::sqrt(2.0));
  r = closestPointOnSegment(Vec3(5, 0, 4), a, b);
  EXPECT_EQ(r.feature, SegmentFeature::End);
  EXPECT_TRUE(allNear(r.closest, b, 0.0));
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
}

TEST(ClosestPointOnSegment, MatchesTheSeedsMinOfThreeFormula) {
  // Seed 004 "Point-Edge": d = min(|(p2 - p1) x (p0 - p1)| / |p2 - p1|, |p0 - p1|, |p0 - p2|) when
  // the perpendicular foot is inside the edge; the end distances otherwise.
  const Vec3 p1(1, 1, 1), p2(3, 2, -1), p0(2, 4, 0);
  const double perpendicular = (p2 - p1).cross(p0 - p1).norm() / (p2 - p1).norm();
  const double seed = std::min({perpendicular, (p0 - p1).norm(), (p0 - p2).norm()});
  EXPECT_NEAR(closestPointOnSegment(p0, p1, p2).distance, seed, 1e-14);
}

TEST(ClosestPointOnSegment, ZeroLengthSegmentIsAPoint) {
  const PointSegmentResult r = closestPointOnSegment(Vec3(0, 3, 4), Vec3(0, 0, 0), Vec3(0, 0, 0));
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
  EXPECT_FALSE(std::isnan(r.t));
}

struct RegionCase {
  Vec3 p;
  Vec3 closest;
  TriangleFeature feature;
};

TEST(ClosestPointOnTriangle, EveryVoronoiRegion) {
  const RegionCase cases[] = {
      {{0.25, 0.25, 2.0}, {0.25, 0.25, 0.0}, TriangleFeature::Face},    // above the interior
      {{0.25, 0.25, -3.0}, {0.25, 0.25, 0.0}, TriangleFeature::Face},   // below it
      {{0.5, -1.0, 1.0}, {0.5, 0.0, 0.0}, TriangleFeature::EdgeAB},
      {{1.0, 1.0, 0.0}, {0.5, 0.5, 0.0}, TriangleFeature::EdgeBC},
      {{-1.0, 0.5, 0.7}, {0.0, 0.5, 0.0}, TriangleFeature::EdgeCA},
      {{-1.0, -1.0, 3.0}, kA, TriangleFeature::VertexA},
      {{2.0, -0.5, 0.0}, kB, TriangleFeature::VertexB},
      {{-0.2, 2.0, -1.0}, kC, TriangleFeature::VertexC},
  };
  for (const RegionCase& c : cases) {
    const PointTriangleResult r = closestPointOnTriangle(c.p, kA, kB, kC);
    EXPECT_EQ(r.feature, c.feature) << c.p.transpose();
    EXPECT_TRUE(allNear(r.closest, c.closest, 1e-15)) << c.p.transpose();
    EXPECT_NEAR(r.distance, (c.p - c.closest).norm(), 1e-15);
    const Vec3 fromWeights = r.barycentric[0] * kA + r.barycentric[1] * kB + r.barycentric[2] * kC;
    EXPECT_TRUE(allNear(fromWeights, r.closest, 1e-15));
  }
}

TEST(ClosestPointOnTriangle, PointOnTheTriangleHasDistanceZero) {
  EXPECT_NEAR(closestPointOnTriangle(Vec3(0.2, 0.3, 0), kA, kB, kC).distance, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(closestPointOnTriangle(kB, kA, kB, kC).distance, 0.0);
}

TEST(ClosestPointOnTriangle, DegenerateTrianglesGiveTheNearestEdgeWithoutNaN) {
  // Collinear vertices, and all three at one point.
  PointTriangleResult r = closestPointOnTriangle(Vec3(1, 1, 0), Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0));
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
  EXPECT_TRUE(allNear(r.closest, Vec3(1, 0, 0), 1e-15));
  r = closestPointOnTriangle(Vec3(0, 3, 4), Vec3::Zero(), Vec3::Zero(), Vec3::Zero());
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
  for (double w : r.barycentric) EXPECT_FALSE(std::isnan(w));
}

// An independent reference in long double: project onto the plane and use barycentric
// coordinates if the foot is inside, otherwise the nearest of the three edges.
using Vec3L = Eigen::Matrix<long double, 3, 1>;

long double refPointSegment(const Vec3L& p, const Vec3L& a, const Vec3L& b) {
  const Vec3L ab = b - a;
  long double t = (p - a).dot(ab) / ab.squaredNorm();
  t = std::max(0.0L, std::min(1.0L, t));
  return (p - (a + t * ab)).norm();
}

long double refPointTriangle(const Vec3& pd, const Vec3& ad, const Vec3& bd, const Vec3& cd) {
  const Vec3L p = pd.cast<long double>(), a = ad.cast<long double>(), b = bd.cast<long double>(),
              c = cd.cast<long double>();
  const Vec3L n = (b - a).cross(c - a);
  const Vec3L foot = p - n * (n.dot(p - a) / n.squaredNorm());
  const long double area = n.squaredNorm();
  const long double u = n.dot((b - foot).cross(c - foot)) / area;
  const long double v = n.dot((c - foot).cross(a - foot)) / area;
  const long double w = 1.0L - u - v;
  if (u >= 0 && v >= 0 && w >= 0) return (p - foot).norm();
  return std::min({refPointSegment(p, a, b), refPointSegment(p, b, c), refPointSegment(p, c, a)});
}

TEST(ClosestPointOnTriangle, RandomCasesMatchALongDoubleReference) {
  std::mt19937 rng(404);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const auto rand3 = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 a = rand3(), b = rand3(), c = rand3(), p = 2.0 * rand3();
    const PointTriangleResult r = closestPointOnTriangle(p, a, b, c);
    const double ref = static_cast<double>(refPointTriangle(p, a, b, c));
    ASSERT_NEAR(r.distance, ref, 1e-12 * (1.0 + ref)) << "trial " << trial;
    // The closest point is on the triangle: convex weights that reproduce it.
    for (double w : r.barycentric) ASSERT_GE(w, -1e-12);
    ASSERT_NEAR(r.barycentric[0] + r.barycentric[1] + r.barycentric[2], 1.0, 1e-12);
    ASSERT_TRUE(allNear(r.barycentric[0] * a + r.barycentric[1] * b + r.barycentric[2] * c, r.closest, 1e-12));
  }
}

TEST(ClosestPointOnTriangle, NoSampledPointOfTheTriangleIsCloser) {
  std::mt19937 rng(405);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  const auto rand3 = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = rand3(), b = rand3(), c = rand3(), p = 2.0 * rand3();
    const double d = closestPointOnTriangle(p, a, b, c).distance;
    double sampled = std::numeric_limits<double>::infinity();
    for (int s = 0; s < 2000; ++s) {
      double x = unit(rng), y = unit(rng);
      if (x + y > 1.0) {  // fold the square's far half onto the triangle
        x = 1.0 - x;
        y = 1.0 - y;
      }
      sampled = std::min(sampled, (p - (a + x * (b - a) + y * (c - a))).norm());
    }
    EXPECT_GE(sampled, d - 1e-12) << "trial " << trial;
    EXPECT_LE(sampled, d + 0.2) << "trial " << trial;  // dense enough to come near the minimum
  }
}

TEST(ClosestPointsSegmentSegment, SkewSegmentsMeetAtTheirCommonPerpendicular) {
  const SegmentSegmentResult r =
      closestPointsSegmentSegment(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 2), Vec3(0.5, 1, 2));
  EXPECT_DOUBLE_EQ(r.distance, 2.0);
  EXPECT_TRUE(allNear(r.closest1, Vec3(0.5, 0, 0), 1e-15));
  EXPECT_TRUE(allNear(r.closest2, Vec3(0.5, 0, 2), 1e-15));
  EXPECT_DOUBLE_EQ(r.s, 0.75);
  EXPECT_DOUBLE_EQ(r.t, 0.5);
}

TEST(ClosestPointsSegmentSegment, CrossingSegmentsHaveDistanceZero) {
  const SegmentSegmentResult r =
      closestPointsSegmentSegment(Vec3(-1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(1, -1, 0));
  EXPECT_NEAR(r.distance, 0.0, 1e-15);
  EXPECT_TRUE(allNear(r.closest1, Vec3::Zero(), 1e-15));
}

TEST(ClosestPointsSegmentSegment, ParallelSegmentsGiveAValidClosestPair) {
  // Overlapping in x over [1, 2], 3 apart in y: any pair in the overlap is closest.
  SegmentSegmentResult r = closestPointsSegmentSegment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 3, 0), Vec3(4, 3, 0));
  EXPECT_DOUBLE_EQ(r.distance, 3.0);
  EXPECT_NEAR((r.closest2 - r.closest1).dot(Vec3::UnitX()), 0.0, 1e-15);
  EXPECT_GE(r.closest1.x(), 1.0);
  // Collinear and disjoint: end to end.
  r = closestPointsSegmentSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(2, 0, 0));
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  EXPECT_TRUE(allNear(r.closest1, Vec3(1, 0, 0), 0.0));
  EXPECT_TRUE(allNear(r.closest2, Vec3(2, 0, 0), 0.0));
}

TEST(ClosestPointsSegmentSegment, EndpointRegionsAndPointSegments) {
  // The perpendicular foot on the second line is past its end: clamped, then s recomputed.
  SegmentSegmentResult r = closestPointsSegmentSegment(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 1, 0), Vec3(3, 5, 0));
  EXPECT_TRUE(allNear(r.closest1, Vec3(1, 0, 0), 1e-15));
  EXPECT_TRUE(allNear(r.closest2, Vec3(3, 1, 0), 1e-15));
  r = closestPointsSegmentSegment(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(-1, 2, 0), Vec3(1, 2, 0));
  EXPECT_DOUBLE_EQ(r.distance, 2.0);
  r = closestPointsSegmentSegment(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 3, 4), Vec3(0, 3, 4));
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
}

// Reference: the distance is convex in s, and for fixed s the best t is a clamped projection, so
// a golden-section search over s finds it to rounding.
double refSegmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const auto f = [&](double s) { return closestPointOnSegment(p1 + s * (q1 - p1), p2, q2).distance; };
  double lo = 0.0, hi = 1.0;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (f(m1) < f(m2)) hi = m2;
    else lo = m1;
  }
  return std::min({f(0.5 * (lo + hi)), f(0.0), f(1.0)});
}

TEST(ClosestPointsSegmentSegment, RandomCasesMatchAGoldenSectionReference) {
  std::mt19937 rng(406);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto rand3 = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int trial = 0; trial < 5000; ++trial) {
    const Vec3 p1 = rand3(), q1 = rand3(), p2 = rand3(), q2 = rand3();
    const SegmentSegmentResult r = closestPointsSegmentSegment(p1, q1, p2, q2);
    ASSERT_NEAR(r.distance, refSegmentSegment(p1, q1, p2, q2), 1e-9) << "trial " << trial;
    ASSERT_TRUE(allNear(r.closest1, p1 + r.s * (q1 - p1), 1e-14));
    ASSERT_TRUE(allNear(r.closest2, p2 + r.t * (q2 - p2), 1e-14));
    ASSERT_NEAR(r.distance, (r.closest1 - r.closest2).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace rbsim
