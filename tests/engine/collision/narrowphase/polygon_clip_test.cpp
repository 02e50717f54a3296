// collision/narrowphase/polygon_clip: Sutherland-Hodgman half-space clipping and the planar hull.
#include "collision/narrowphase/polygon_clip.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

const std::vector<Vec3> kSquare = {Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(1, 0, 1), Vec3(-1, 0, 1)};

bool contains(const std::vector<Vec3>& pts, const Vec3& p, double tol = 1e-15) {
  for (const Vec3& q : pts) {
    if ((q - p).norm() <= tol) return true;
  }
  return false;
}

TEST(ClipByHalfSpace, SquareCutThroughTheMiddle) {
  const std::vector<Vec3> out = clipByHalfSpace(kSquare, Vec3::UnitX(), 0.25);  // keep x <= 0.25
  ASSERT_EQ(out.size(), 4u);
  for (const Vec3& p : {Vec3(-1, 0, -1), Vec3(0.25, 0, -1), Vec3(0.25, 0, 1), Vec3(-1, 0, 1)}) {
    EXPECT_TRUE(contains(out, p)) << p.transpose();
  }
}

TEST(ClipByHalfSpace, CornerCutAddsAVertex) {
  // Keep x + z <= 1.5: cuts the (1, 1) corner off, giving a pentagon.
  const Vec3 n = Vec3(1, 0, 1).normalized();
  const std::vector<Vec3> out = clipByHalfSpace(kSquare, n, 1.5 / std::sqrt(2.0));
  ASSERT_EQ(out.size(), 5u);
  EXPECT_TRUE(contains(out, Vec3(1, 0, 0.5), 1e-15));
  EXPECT_TRUE(contains(out, Vec3(0.5, 0, 1), 1e-15));
}

TEST(ClipByHalfSpace, AllInsideAllOutsidePointsAndSegments) {
  EXPECT_EQ(clipByHalfSpace(kSquare, Vec3::UnitY(), 0.0).size(), 4u);  // on the plane counts as inside
  EXPECT_TRUE(clipByHalfSpace(kSquare, Vec3::UnitX(), -2.0).empty());
  EXPECT_EQ(clipByHalfSpace({Vec3(0, 0, 0)}, Vec3::UnitX(), 0.5).size(), 1u);
  EXPECT_TRUE(clipByHalfSpace({Vec3(1, 0, 0)}, Vec3::UnitX(), 0.5).empty());
  const std::vector<Vec3> seg = clipByHalfSpace({Vec3(-1, 0, 0), Vec3(1, 0, 0)}, Vec3::UnitX(), 0.5);
  ASSERT_EQ(seg.size(), 2u);
  EXPECT_TRUE(allNear(seg[0], Vec3(-1, 0, 0), 0.0));
  EXPECT_TRUE(allNear(seg[1], Vec3(0.5, 0, 0), 1e-15));
  EXPECT_TRUE(clipByHalfSpace({}, Vec3::UnitX(), 0.0).empty());
}

TEST(PlanarConvexHull, DropsInteriorAndCollinearPointsAndWindsCounterClockwise) {
  std::vector<Vec3> pts = kSquare;
  pts.push_back(Vec3(0, 0.3, 0));    // interior (and off the plane: projected along y)
  pts.push_back(Vec3(1, 0, 0));      // on an edge
  pts.push_back(Vec3(-1, 0, -1));    // duplicate
  const std::vector<Vec3> hull = planarConvexHull(pts, Vec3::UnitY(), 1e-9);
  ASSERT_EQ(hull.size(), 4u);
  for (const Vec3& c : kSquare) EXPECT_TRUE(contains(hull, c));
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec3& a = hull[i];
    const Vec3& b = hull[(i + 1) % 4];
    const Vec3& c = hull[(i + 2) % 4];
    EXPECT_GT((b - a).cross(c - b).dot(Vec3::UnitY()), 0.0);  // left turns about the axis
  }
}

TEST(PlanarConvexHull, CollinearGivesTheTwoEndsAndCoincidentGivesOnePoint) {
  const std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0)};
  // Seen along y the fourth point is on the line too.
  std::vector<Vec3> hull = planarConvexHull(line, Vec3::UnitY(), 1e-9);
  ASSERT_EQ(hull.size(), 2u);
  EXPECT_TRUE(contains(hull, Vec3(0, 0, 0)));
  EXPECT_TRUE(contains(hull, Vec3(2, 0, 0)));
  hull = planarConvexHull({Vec3(1, 0, 1), Vec3(1, 5, 1), Vec3(1, -2, 1)}, Vec3::UnitY(), 1e-9);
  EXPECT_EQ(hull.size(), 1u);
  EXPECT_EQ(planarConvexHull({}, Vec3::UnitY(), 1e-9).size(), 0u);
}

}  // namespace
}  // namespace rbsim
