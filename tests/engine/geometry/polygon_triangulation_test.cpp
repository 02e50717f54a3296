// geometry/polygon_triangulation: ear clipping of OBJ faces keeps area and winding, and refuses
// polygons that have no area or cross themselves instead of inventing triangles.
#include "geometry/polygon_triangulation.h"

#include <gtest/gtest.h>

namespace rbsim {
namespace {

// Sum of the triangles' vector areas: for a planar polygon, its area times its normal.
Vec3 vectorArea(const std::vector<Vec3>& v, const std::vector<Triangle>& tris) {
  Vec3 sum = Vec3::Zero();
  for (const Triangle& t : tris) sum += 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
  return sum;
}

std::vector<std::uint32_t> inOrder(std::size_t n) {
  std::vector<std::uint32_t> c(n);
  for (std::size_t i = 0; i < n; ++i) c[i] = static_cast<std::uint32_t>(i);
  return c;
}

TEST(TriangulatePolygon, ConcaveArrowKeepsItsAreaAndWinding) {
  // An arrow head in the plane z = 2 (area 3), counter-clockwise seen from +z; corner 3 is reflex,
  // so a fan from corner 0 would cover the notch.
  const std::vector<Vec3> arrow = {{0, 0, 2}, {4, 0, 2}, {4, 4, 2}, {2, 1, 2}, {0, 4, 2}};
  std::vector<Triangle> out;
  ASSERT_TRUE(triangulatePolygon(arrow, inOrder(5), out));
  ASSERT_EQ(out.size(), 3u);
  const Vec3 area = vectorArea(arrow, out);
  EXPECT_NEAR(area.z(), 10.0, 1e-12) << "16 minus the notch of 6";
  EXPECT_NEAR(area.x(), 0.0, 1e-12);
  for (const Triangle& t : out) {
    EXPECT_GT((arrow[t[1]] - arrow[t[0]]).cross(arrow[t[2]] - arrow[t[0]]).z(), 0.0) << "no flipped triangle";
  }
}

TEST(TriangulatePolygon, ClockwiseSeenFromPlusZStaysClockwise) {
  const std::vector<Vec3> square = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  std::vector<Triangle> out;
  ASSERT_TRUE(triangulatePolygon(square, inOrder(4), out));
  EXPECT_NEAR(vectorArea(square, out).z(), -1.0, 1e-15);
}

TEST(TriangulatePolygon, CollinearCornersHaveNoAreaAndAreRefused) {
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  std::vector<Triangle> out;
  EXPECT_FALSE(triangulatePolygon(line, inOrder(4), out));
  EXPECT_TRUE(out.empty());
}

TEST(TriangulatePolygon, ABowTieWithNoNetAreaIsRefused) {
  // Self-intersecting: its two lobes cancel, so the Newell normal is zero.
  const std::vector<Vec3> bowTie = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Triangle> out;
  EXPECT_FALSE(triangulatePolygon(bowTie, inOrder(4), out));
}

TEST(TriangulatePolygon, ASelfCrossingPentagramIsRefused) {
  // The five-pointed star drawn in one stroke: its net area is not zero and no corner lies inside
  // another's ear (all five lie on one circle), so only the crossing edges give it away.
  std::vector<Vec3> star;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * M_PI * (2 * k) / 5.0;
    star.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  std::vector<Triangle> out;
  EXPECT_FALSE(triangulatePolygon(star, inOrder(5), out));
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace rbsim
