// The debug shape builders: an AABB is exactly its 12 axis-aligned edges, and an arrow is its
// shaft plus a head that ends at the tip.
#include <cmath>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "render/debug_shapes.h"

namespace rbsim::render::test {
namespace {

TEST(DebugShapes, BoxIsItsTwelveAxisAlignedEdges) {
  std::vector<DebugLine> lines;
  const glm::vec3 lo{-1.0f, 0.0f, 2.0f}, hi{1.0f, 0.5f, 5.0f};
  appendBoxLines(lines, lo, hi, {1, 0, 0}, true);
  ASSERT_EQ(lines.size(), 12u);
  std::set<std::tuple<float, float, float, float, float, float>> distinct;
  int perAxis[3] = {0, 0, 0};
  for (const DebugLine& line : lines) {
    EXPECT_TRUE(line.onTop);
    const glm::vec3 d = line.b - line.a;
    int changed = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (d[axis] == 0.0f) continue;
      ++changed;
      ++perAxis[axis];
      EXPECT_EQ(std::abs(d[axis]), hi[axis] - lo[axis]);
    }
    EXPECT_EQ(changed, 1);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_TRUE(line.a[axis] == lo[axis] || line.a[axis] == hi[axis]);
    }
    distinct.insert({line.a.x, line.a.y, line.a.z, line.b.x, line.b.y, line.b.z});
  }
  EXPECT_EQ(distinct.size(), 12u);
  EXPECT_EQ(perAxis[0], 4);
  EXPECT_EQ(perAxis[1], 4);
  EXPECT_EQ(perAxis[2], 4);
}

TEST(DebugShapes, ArrowIsAShaftAndAHeadAtTheTip) {
  std::vector<DebugLine> lines;
  const glm::vec3 from{1, 1, 1}, to{1, 1.5f, 1};
  appendArrowLines(lines, from, to, {1, 0, 1});
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0].a, from);
  EXPECT_EQ(lines[0].b, to);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_TRUE(lines[i].onTop);
    EXPECT_EQ(lines[i].a, to);
    EXPECT_LT(lines[i].b.y, to.y);  // the head flares back towards the tail
    EXPECT_NEAR(to.y - lines[i].b.y, 0.08f, 1e-5f);  // capped head length
  }
  lines.clear();
  appendArrowLines(lines, from, from, {1, 0, 1});  // no direction: just the (empty) shaft
  EXPECT_EQ(lines.size(), 1u);
}

}  // namespace
}  // namespace rbsim::render::test
