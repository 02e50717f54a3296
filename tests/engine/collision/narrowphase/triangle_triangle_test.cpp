// collision/narrowphase/triangle_triangle: Moller's test (seed 004 "Triangle intersection") on
// hand-made cases, and against an independent edge-through-triangle check on random triangles.
#include "collision/narrowphase/triangle_triangle.h"

#include <array>
#include <random>

#include <gtest/gtest.h>

#include "geometry/distance.h"
#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;
using Tri = std::array<Vec3, 3>;

// T1 in the plane z = 0: the right triangle with legs 2 along x and y.
const Tri kT1 = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};

TriTriResult test(const Tri& a, const Tri& b) { return triangleTriangleIntersection(a[0], a[1], a[2], b[0], b[1], b[2]); }

Tri shifted(const Tri& t, const Vec3& d) { return {t[0] + d, t[1] + d, t[2] + d}; }

TEST(TriangleTriangle, CrossingTrianglesGiveTheirIntersectionSegment) {
  const Tri t2 = {Vec3(0.5, 0.2, -1), Vec3(0.5, 0.2, 1), Vec3(0.5, 1.0, 0)};
  const TriTriResult r = test(kT1, t2);
  ASSERT_TRUE(r.intersect);
  EXPECT_FALSE(r.coplanar);
  ASSERT_TRUE(r.hasSegment);
  // T2 cuts z = 0 along x = 0.5, y in [0.2, 1], all of it inside T1.
  const bool forward = r.segment[0].y() < r.segment[1].y();
  EXPECT_TRUE(allNear(r.segment[forward ? 0 : 1], Vec3(0.5, 0.2, 0), 1e-15));
  EXPECT_TRUE(allNear(r.segment[forward ? 1 : 0], Vec3(0.5, 1.0, 0), 1e-15));
  // Symmetric in the two triangles.
  EXPECT_TRUE(test(t2, kT1).intersect);
}

TEST(TriangleTriangle, SegmentIsClippedToBothTriangles) {
  // T2 pierces T1's plane along y = 0.5 from x = -1 to x = 3; T1 spans x in [0, 1.5] there.
  const Tri t2 = {Vec3(-1, 0.5, -1), Vec3(3, 0.5, -1), Vec3(1, 0.5, 3)};
  const TriTriResult r = test(kT1, t2);
  ASSERT_TRUE(r.hasSegment);
  const double lo = std::min(r.segment[0].x(), r.segment[1].x()), hi = std::max(r.segment[0].x(), r.segment[1].x());
  EXPECT_NEAR(lo, 0.0, 1e-15);
  EXPECT_NEAR(hi, 1.5, 1e-15);
  EXPECT_NEAR(r.segment[0].y(), 0.5, 1e-15);
  EXPECT_NEAR(r.segment[1].z(), 0.0, 1e-15);
}

TEST(TriangleTriangle, TouchingAtAVertexIntersects) {
  // T2's vertex on T1's interior, the rest above it.
  const Tri t2 = {Vec3(0.5, 0.5, 0), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  const TriTriResult r = test(kT1, t2);
  ASSERT_TRUE(r.intersect);
  ASSERT_TRUE(r.hasSegment);
  EXPECT_TRUE(allNear(r.segment[0], Vec3(0.5, 0.5, 0), 1e-15));
  EXPECT_TRUE(allNear(r.segment[1], Vec3(0.5, 0.5, 0), 1e-15));
  // Vertex to vertex.
  EXPECT_TRUE(test(kT1, {Vec3(2, 0, 0), Vec3(3, 1, 1), Vec3(3, -1, 1)}).intersect);
  // Lifted by a micrometre it no longer touches.
  EXPECT_FALSE(test(kT1, shifted(t2, Vec3(0, 0, 1e-6))).intersect);
}

TEST(TriangleTriangle, SharingAnEdgeAtAnAngleIntersectsAlongIt) {
  const Tri t2 = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 1)};
  const TriTriResult r = test(kT1, t2);
  ASSERT_TRUE(r.hasSegment);
  EXPECT_NEAR((r.segment[1] - r.segment[0]).norm(), 2.0, 1e-15);
}

TEST(TriangleTriangle, CoplanarOverlapContainmentAndDisjoint) {
  TriTriResult r = test(kT1, {Vec3(0.5, 0.5, 0), Vec3(3, 0.5, 0), Vec3(0.5, 3, 0)});
  EXPECT_TRUE(r.coplanar);
  EXPECT_TRUE(r.intersect);
  // Inside T1 with no edge crossings: caught by the containment test, both ways round.
  const Tri inner = {Vec3(0.2, 0.2, 0), Vec3(0.5, 0.2, 0), Vec3(0.2, 0.5, 0)};
  EXPECT_TRUE(test(kT1, inner).intersect);
  EXPECT_TRUE(test(inner, kT1).intersect);
  r = test(kT1, {Vec3(3, 3, 0), Vec3(4, 3, 0), Vec3(3, 4, 0)});
  EXPECT_TRUE(r.coplanar);
  EXPECT_FALSE(r.intersect);
  // Coplanar, touching at one vertex.
  EXPECT_TRUE(test(kT1, {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0)}).intersect);
}

TEST(TriangleTriangle, FarApartAndOneSidedRejections) {
  EXPECT_FALSE(test(kT1, shifted(kT1, Vec3(10, 10, 10))).intersect);
  // Seed 004 "Why do we need to check both planes?": T1 straddles T2's plane, but T2 lies
  // entirely above T1's plane, so only the second plane test rejects it.
  const Tri t2 = {Vec3(0.5, 0, 1), Vec3(0.5, 1, 1), Vec3(0.5, 0, 2)};
  EXPECT_FALSE(test(kT1, t2).intersect);
  // Both straddle the other's plane but their intervals on the common line are disjoint.
  EXPECT_FALSE(test(kT1, {Vec3(0.5, 5, -1), Vec3(0.5, 5, 1), Vec3(0.5, 6, 0)}).intersect);
}

TEST(TriangleTriangle, DegenerateTrianglesAreTestedAsSegments) {
  TriTriResult r = test(kT1, {Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, 0)});
  EXPECT_TRUE(r.degenerate);
  EXPECT_TRUE(r.intersect);
  EXPECT_FALSE(test(kT1, {Vec3(5, 0.5, -1), Vec3(5, 0.5, 1), Vec3(5, 0.5, 0)}).intersect);
  EXPECT_TRUE(test({Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)}, {Vec3(0, 2, 2), Vec3(2, 0, 0), Vec3(1, 1, 1)}).intersect);
}

// Independent check: closed triangles meet iff an edge of one meets the other (the ends of their
// intersection lie on edges). Edge vs triangle by Moller-Trumbore in long double.
using Vec3L = Eigen::Matrix<long double, 3, 1>;

bool edgeHitsTriangle(const Vec3& pd, const Vec3& qd, const Tri& t) {
  const Vec3L p = pd.cast<long double>(), d = (qd - pd).cast<long double>();
  const Vec3L a = t[0].cast<long double>(), e1 = (t[1] - t[0]).cast<long double>(), e2 = (t[2] - t[0]).cast<long double>();
  const Vec3L h = d.cross(e2);
  const long double det = e1.dot(h), f = 1.0L / det;
  const Vec3L s = p - a;
  const long double u = f * s.dot(h);
  if (u < 0 || u > 1) return false;
  const Vec3L q = s.cross(e1);
  const long double v = f * d.dot(q);
  if (v < 0 || u + v > 1) return false;
  const long double tt = f * e2.dot(q);
  return tt >= 0 && tt <= 1;
}

bool referenceIntersect(const Tri& a, const Tri& b) {
  for (int e = 0; e < 3; ++e) {
    if (edgeHitsTriangle(a[e], a[(e + 1) % 3], b) || edgeHitsTriangle(b[e], b[(e + 1) % 3], a)) return true;
  }
  return false;
}

TEST(TriangleTriangle, RandomPairsAgreeWithEdgeThroughTriangleReference) {
  std::mt19937 rng(407);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto rand3 = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Tri a = {rand3(), rand3(), rand3()}, b = {rand3(), rand3(), rand3()};
    const TriTriResult r = test(a, b);
    const bool ref = referenceIntersect(a, b);
    ASSERT_EQ(r.intersect, ref) << "trial " << trial;
    hits += ref;
    if (r.hasSegment) {
      for (const Vec3& p : r.segment) {
        ASSERT_LE(closestPointOnTriangle(p, a[0], a[1], a[2]).distance, 1e-9) << "trial " << trial;
        ASSERT_LE(closestPointOnTriangle(p, b[0], b[1], b[2]).distance, 1e-9) << "trial " << trial;
      }
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(hits, 2000);
  EXPECT_LT(hits, 18000);
}

// Coplanar reference: 2D separating axes (edge normals of both triangles).
bool separated2d(const std::array<Eigen::Vector2d, 3>& a, const std::array<Eigen::Vector2d, 3>& b) {
  for (const auto* t : {&a, &b}) {
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector2d d = (*t)[(e + 1) % 3] - (*t)[e];
      const Eigen::Vector2d n(-d.y(), d.x());
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (int k = 0; k < 3; ++k) {
        amin = std::min(amin, n.dot(a[k]));
        amax = std::max(amax, n.dot(a[k]));
        bmin = std::min(bmin, n.dot(b[k]));
        bmax = std::max(bmax, n.dot(b[k]));
      }
      if (amax < bmin || bmax < amin) return true;
    }
  }
  return false;
}

TEST(TriangleTriangle, RandomCoplanarPairsAgreeWithTwoDimensionalSeparatingAxes) {
  std::mt19937 rng(408);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    // Random triangles in z = 0 of a random rigid frame.
    const Mat3 R = Quat(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    const Vec3 origin(u(rng), u(rng), u(rng));
    std::array<Eigen::Vector2d, 3> a2, b2;
    Tri a, b;
    for (int k = 0; k < 3; ++k) {
      a2[k] = {u(rng), u(rng)};
      b2[k] = {u(rng) + 0.6, u(rng)};
      a[k] = R * Vec3(a2[k].x(), a2[k].y(), 0) + origin;
      b[k] = R * Vec3(b2[k].x(), b2[k].y(), 0) + origin;
    }
    const TriTriResult r = test(a, b);
    const bool ref = !separated2d(a2, b2);
    ASSERT_TRUE(r.coplanar) << "trial " << trial;
    ASSERT_EQ(r.intersect, ref) << "trial " << trial;
    hits += ref;
  }
  EXPECT_GT(hits, 500);
  EXPECT_LT(hits, 4500);
}

}  // namespace
}  // namespace rbsim
