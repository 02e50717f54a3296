// geometry/csg: union min(a, b), intersection max(a, b) and difference max(a, -b) of the operands'
// signed distances, operands placed by a rigid motion, and the bounds the grids are laid over.
#include "geometry/csg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "test_util.h"

namespace rbsim {
namespace {

using test::allNear;

ImplicitFunction sphere(double r, const Vec3& at = Vec3::Zero()) { return ImplicitFunction::primitive(SphereSurface{r}, at); }

TEST(Csg, OperationsAreMinMaxAndMaxOfNegatedOnRandomPoints) {
  const Vec3 offset(0.3, 0.1, -0.2);
  const SphereSurface a{0.5};
  const BoxSurface b{Vec3(0.4, 0.2, 0.3)};
  const auto bAt = [&](const Vec3& p) { return b.phi(p - offset); };
  const ImplicitFunction A = ImplicitFunction::primitive(a), B = ImplicitFunction::primitive(b, offset);
  const ImplicitFunction u = ImplicitFunction::combine(CsgOp::Union, A, B);
  const ImplicitFunction i = ImplicitFunction::combine(CsgOp::Intersection, A, B);
  const ImplicitFunction d = ImplicitFunction::combine(CsgOp::Difference, A, B);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (int n = 0; n < 500; ++n) {
    const Vec3 p(r(rng), r(rng), r(rng));
    EXPECT_EQ(u.phi(p), std::min(a.phi(p), bAt(p)));
    EXPECT_EQ(i.phi(p), std::max(a.phi(p), bAt(p)));
    EXPECT_EQ(d.phi(p), std::max(a.phi(p), -bAt(p)));
  }
}

TEST(Csg, ACupIsACylinderMinusACylinder) {
  // Outer radius 0.5 m, height 0.6 m; the inner one (0.44 m) from 0.06 m above the bottom up
  // through the rim.
  const ImplicitFunction cup = ImplicitFunction::combine(
      CsgOp::Difference, ImplicitFunction::primitive(CylinderSurface{0.5, 0.3}),
      ImplicitFunction::primitive(CylinderSurface{0.44, 0.3}, Vec3(0.0, 0.06, 0.0)));
  EXPECT_NEAR(cup.phi(Vec3(0.0, 0.0, 0.0)), 0.24, 1e-12);    // in the cavity, 0.24 m above the floor
  EXPECT_NEAR(cup.phi(Vec3(0.0, -0.27, 0.0)), -0.03, 1e-12); // mid-floor
  EXPECT_NEAR(cup.phi(Vec3(0.47, 0.0, 0.0)), -0.03, 1e-12);  // mid-wall
  EXPECT_NEAR(cup.phi(Vec3(0.0, 0.0, 0.8)), 0.3, 1e-12);     // outside beside it
  EXPECT_EQ(cup.depth(), 1);
  EXPECT_EQ(cup.primitiveCount(), 2);
  const ImplicitBounds b = cup.bounds();
  EXPECT_TRUE(allNear(b.lo, Vec3(-0.5, -0.3, -0.5), 1e-15));
  EXPECT_TRUE(allNear(b.hi, Vec3(0.5, 0.3, 0.5), 1e-15));
}

TEST(Csg, ARotatedOperandIsEvaluatedInItsOwnFrame) {
  // A capsule along y turned 90 degrees about z lies along x.
  const Quat turn(Eigen::AngleAxisd(M_PI / 2.0, Vec3::UnitZ()));
  const ImplicitFunction c = ImplicitFunction::primitive(CapsuleSurface{0.1, 0.5}, Vec3(0.0, 1.0, 0.0), turn);
  EXPECT_NEAR(c.phi(Vec3(0.5, 1.0, 0.0)), -0.1, 1e-12);
  EXPECT_NEAR(c.phi(Vec3(0.0, 1.5, 0.0)), 0.4, 1e-12);
  const ImplicitBounds b = c.bounds();
  EXPECT_TRUE(allNear(b.lo, Vec3(-0.6, 0.9, -0.1), 1e-12));
  EXPECT_TRUE(allNear(b.hi, Vec3(0.6, 1.1, 0.1), 1e-12));
}

TEST(Csg, BoundsOfUnionIntersectionAndDisjointIntersection) {
  const ImplicitFunction a = sphere(0.5), b = sphere(0.5, Vec3(0.8, 0.0, 0.0)), far = sphere(0.5, Vec3(3.0, 0.0, 0.0));
  const ImplicitBounds u = ImplicitFunction::combine(CsgOp::Union, a, b).bounds();
  EXPECT_TRUE(allNear(u.lo, Vec3(-0.5, -0.5, -0.5), 1e-15));
  EXPECT_TRUE(allNear(u.hi, Vec3(1.3, 0.5, 0.5), 1e-15));
  const ImplicitBounds i = ImplicitFunction::combine(CsgOp::Intersection, a, b).bounds();
  EXPECT_TRUE(allNear(i.lo, Vec3(0.3, -0.5, -0.5), 1e-15));
  EXPECT_TRUE(allNear(i.hi, Vec3(0.5, 0.5, 0.5), 1e-15));
  EXPECT_TRUE(ImplicitFunction::combine(CsgOp::Intersection, a, far).bounds().empty());
  EXPECT_FALSE(ImplicitFunction::combine(CsgOp::Difference, a, far).bounds().empty());
}

TEST(Csg, DepthCountsNestedOperations) {
  ImplicitFunction f = sphere(1.0);
  for (int level = 1; level <= 5; ++level) {
    f = ImplicitFunction::combine(CsgOp::Union, f, sphere(0.5, Vec3(level, 0.0, 0.0)));
    EXPECT_EQ(f.depth(), level);
    EXPECT_EQ(f.primitiveCount(), level + 1);
  }
}

}  // namespace
}  // namespace rbsim
