// collision/narrowphase/manifold_reduction: deepest, farthest, largest triangle, largest added
// area; duplicates and collinear extras dropped.
#include "collision/narrowphase/manifold_reduction.h"

#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

bool holds(const ContactManifold& m, const Vec3& p) {
  for (int i = 0; i < m.count; ++i) {
    if ((m.points[i].position - p).norm() < 1e-12) return true;
  }
  return false;
}

TEST(ReduceContacts, EmptyAndFewPoints) {
  EXPECT_EQ(reduceContacts({}, Vec3::UnitY()).count, 0);
  const std::vector<ContactPoint> three = {{Vec3(0, 0, 0), 0.1}, {Vec3(1, 0, 0), 0.2}, {Vec3(0, 0, 1), 0.3}};
  const ContactManifold m = reduceContacts(three, Vec3::UnitY());
  EXPECT_EQ(m.count, 3);
  EXPECT_TRUE(allNear(m.normal, Vec3::UnitY(), 0.0));
  EXPECT_DOUBLE_EQ(m.points[0].depth, 0.3);  // the deepest comes first
}

TEST(ReduceContacts, DuplicatesCollapseToOnePoint) {
  const std::vector<ContactPoint> same(5, ContactPoint{Vec3(1, 2, 3), 0.01});
  EXPECT_EQ(reduceContacts(same, Vec3::UnitY()).count, 1);
}

TEST(ReduceContacts, CollinearPointsKeepTheDeepestAndTheFarthest) {
  std::vector<ContactPoint> line;
  for (int i = 0; i <= 4; ++i) line.push_back({Vec3(i, 0.01 * i, 0), i == 2 ? 0.5 : 0.1});
  const ContactManifold m = reduceContacts(line, Vec3::UnitY());
  ASSERT_EQ(m.count, 2);
  EXPECT_TRUE(holds(m, Vec3(2, 0.02, 0)));
  // Both ends are 2 from the deepest; the first found wins.
  EXPECT_TRUE(holds(m, Vec3(0, 0, 0)) || holds(m, Vec3(4, 0.04, 0)));
}

TEST(ReduceContacts, OctagonKeepsTheDeepestAndALargeQuadrilateral) {
  std::vector<ContactPoint> ring;
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4.0;
    ring.push_back({Vec3(std::cos(a), 0, std::sin(a)), k == 3 ? 0.2 : 0.1});
  }
  const ContactManifold m = reduceContacts(ring, Vec3::UnitY());
  ASSERT_EQ(m.count, 4);
  EXPECT_DOUBLE_EQ(m.points[0].depth, 0.2);
  // The deepest, its opposite, and the two at right angles: the inscribed square, area 2.
  EXPECT_TRUE(holds(m, ring[3].position));
  EXPECT_TRUE(holds(m, ring[7].position));
  EXPECT_TRUE(holds(m, ring[1].position));
  EXPECT_TRUE(holds(m, ring[5].position));
}

TEST(ReduceContacts, DistancesAreMeasuredInTheContactPlane) {
  // Two points differing only along the normal are one contact location.
  const std::vector<ContactPoint> pts = {{Vec3(0, 0, 0), 0.1}, {Vec3(0, 0.5, 0), 0.2}};
  EXPECT_EQ(reduceContacts(pts, Vec3::UnitY()).count, 1);
}

}  // namespace
}  // namespace rbsim
