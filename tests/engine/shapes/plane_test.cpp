// The plane (shapes/plane.h): signed distance and ray hits against their definitions.
#include <cmath>

#include <gtest/gtest.h>

#include "rbsim/shapes/plane.h"

namespace rbsim {
namespace {

TEST(Plane, SignedDistanceAndRayHits) {
  const Plane tilted{Vec3(0.0, 0.6, 0.8), 1.0};  // n . p = 1
  EXPECT_DOUBLE_EQ(tilted.signedDistance(Vec3(0.0, 0.0, 0.0)), -1.0);
  EXPECT_DOUBLE_EQ(tilted.signedDistance(Vec3(0.0, 3.0, 4.0)), 4.0);
  // From 4 m out along -n: hits after 4 m, at the plane.
  const Vec3 origin(0.0, 3.0, 4.0), down(0.0, -0.6, -0.8);
  const double t = tilted.rayHit(origin, down);
  EXPECT_NEAR(t, 4.0, 1e-15);
  EXPECT_NEAR(tilted.signedDistance(origin + t * down), 0.0, 1e-15);
  EXPECT_NEAR(tilted.rayHit(origin, 2.0 * down), 2.0, 1e-15);  // t scales with |direction|
  EXPECT_TRUE(std::isinf(tilted.rayHit(origin, -down)));                  // leaving
  EXPECT_TRUE(std::isinf(tilted.rayHit(origin, Vec3(1.0, 0.0, 0.0))));    // parallel
  EXPECT_TRUE(std::isinf(tilted.rayHit(Vec3::Zero(), down)));             // starting inside
}

}  // namespace
}  // namespace rbsim
