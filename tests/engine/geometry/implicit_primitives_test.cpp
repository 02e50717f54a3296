// geometry/implicit_primitives: the torus's, capsule's and cylinder's exact signed distances at
// points whose nearest surface point is known by hand, and |grad phi| = 1 away from the medial axis.
#include "geometry/implicit_primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace rbsim {
namespace {

constexpr double kExact = 1e-12;  // [m]: closed forms, only rounding

TEST(ImplicitPrimitives, TorusDistanceAtKnownPoints) {
  const TorusSurface t{0.5, 0.15};
  EXPECT_NEAR(t.phi(Vec3(0.5, 0.0, 0.0)), -0.15, kExact);           // on the ring: the tube's radius deep
  EXPECT_NEAR(t.phi(Vec3(0.0, 0.0, 0.0)), 0.35, kExact);            // the centre of the hole
  EXPECT_NEAR(t.phi(Vec3(0.0, 0.0, -0.9)), 0.25, kExact);           // outside, in the plane
  EXPECT_NEAR(t.phi(Vec3(0.0, 0.4, 0.5)), 0.4 - 0.15, kExact);      // straight above the ring
  EXPECT_NEAR(t.phi(Vec3(0.3, 0.4, 0.4)), std::hypot(0.0, 0.4) - 0.15, kExact);  // |(x, z)| = 0.5
  EXPECT_NEAR(t.phi(Vec3(0.6, 0.0, 0.8)), std::hypot(0.5, 0.0) - 0.15, kExact);
}

TEST(ImplicitPrimitives, CapsuleDistanceAtKnownPoints) {
  const CapsuleSurface c{0.2, 0.5};
  EXPECT_NEAR(c.phi(Vec3::Zero()), -0.2, kExact);
  EXPECT_NEAR(c.phi(Vec3(0.5, 0.3, 0.0)), 0.3, kExact);             // beside the segment
  EXPECT_NEAR(c.phi(Vec3(0.0, 1.0, 0.0)), 0.3, kExact);             // beyond a cap, on the axis
  EXPECT_NEAR(c.phi(Vec3(0.3, -0.9, 0.4)), std::sqrt(0.09 + 0.16 + 0.16) - 0.2, kExact);  // off a cap
  EXPECT_NEAR(c.phi(Vec3(0.0, 0.5, 0.1)), -0.1, kExact);
}

TEST(ImplicitPrimitives, CylinderDistanceAtKnownPoints) {
  const CylinderSurface c{0.5, 0.3};
  EXPECT_NEAR(c.phi(Vec3::Zero()), -0.3, kExact);                   // nearer the ends than the side
  EXPECT_NEAR(c.phi(Vec3(0.45, 0.0, 0.0)), -0.05, kExact);          // nearer the side
  EXPECT_NEAR(c.phi(Vec3(0.0, 0.0, 0.8)), 0.3, kExact);             // beside
  EXPECT_NEAR(c.phi(Vec3(0.0, -0.5, 0.2)), 0.2, kExact);            // below the bottom
  EXPECT_NEAR(c.phi(Vec3(0.6, 0.7, 0.8)), std::hypot(0.5, 0.4), kExact);  // off the rim
}

// An exact distance has unit gradient wherever it is differentiable: central differences at random
// points (the chance of one landing within a step of a crease, the medial axis, is ~1e-6).
template <class Surface>
int nonUnitGradients(const Surface& s) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  constexpr double step = 1e-7;  // [m]
  int count = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p(u(rng), u(rng), u(rng));
    Vec3 g;
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 e = Vec3::Zero();
      e[axis] = step;
      g[axis] = (s.phi(p + e) - s.phi(p - e)) / (2.0 * step);
    }
    if (std::abs(g.norm() - 1.0) > 1e-5) ++count;
  }
  return count;
}

TEST(ImplicitPrimitives, GradientsHaveUnitLength) {
  EXPECT_EQ(nonUnitGradients(TorusSurface{0.5, 0.15}), 0);
  EXPECT_EQ(nonUnitGradients(CapsuleSurface{0.2, 0.5}), 0);
  EXPECT_EQ(nonUnitGradients(CylinderSurface{0.5, 0.3}), 0);
}

}  // namespace
}  // namespace rbsim
