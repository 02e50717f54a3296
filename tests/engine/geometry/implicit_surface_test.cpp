// geometry/implicit_surface: exact signed distances of the sphere and the box, the ellipsoid's
// first-order distance against the true distance, and every gradient against finite differences.
#include "geometry/implicit_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace rbsim {
namespace {

constexpr double kFiniteDifferenceStep = 1e-6;  // [m] central differences
constexpr double kFiniteDifferenceTolerance = 1e-6;  // [1] per gradient component

template <class Surface>
Vec3 centralDifference(const Surface& s, const Vec3& p) {
  Vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 e = Vec3::Zero();
    e[axis] = kFiniteDifferenceStep;
    g[axis] = (s.phi(p + e) - s.phi(p - e)) / (2.0 * kFiniteDifferenceStep);
  }
  return g;
}

Vec3 randomPoint(std::mt19937& rng, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  return {u(rng), u(rng), u(rng)};
}

// The true distance from p to the ellipsoid sum (x_i / r_i)^2 = 1 (Eberly, "Distance from a point
// to an ellipsoid"): the closest point is x_i = r_i^2 p_i / (r_i^2 + t) for the single root t >
// -min r_i^2 of sum (r_i p_i / (r_i^2 + t))^2 = 1, which is decreasing there; found by bisection.
double trueEllipsoidDistance(const Vec3& r, const Vec3& p) {
  const auto f = [&](double t) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += std::pow(r[i] * p[i] / (r[i] * r[i] + t), 2);
    return s - 1.0;
  };
  double lo = -r.minCoeff() * r.minCoeff() * (1.0 - 1e-15), hi = 1e3;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  Vec3 x;
  for (int i = 0; i < 3; ++i) x[i] = r[i] * r[i] * p[i] / (r[i] * r[i] + t);
  const double sign = (p.cwiseQuotient(r).squaredNorm() < 1.0) ? -1.0 : 1.0;
  return sign * (p - x).norm();
}

TEST(SphereSurface, IsTheExactSignedDistanceWithUnitGradient) {
  const SphereSurface sphere{0.7};
  EXPECT_DOUBLE_EQ(sphere.phi(Vec3(0.0, 0.0, 0.0)), -0.7);
  EXPECT_DOUBLE_EQ(sphere.phi(Vec3(0.0, 2.0, 0.0)), 1.3);
  EXPECT_DOUBLE_EQ(sphere.phi(Vec3(0.3, 0.0, -0.4)), -0.2);
  std::mt19937 rng(1);
  for (int n = 0; n < 1000; ++n) {
    const Vec3 p = randomPoint(rng, 2.0);
    if (p.norm() < 1e-3) continue;
    EXPECT_NEAR(sphere.gradient(p).norm(), 1.0, 1e-15);
    EXPECT_LT((sphere.gradient(p) - centralDifference(sphere, p)).cwiseAbs().maxCoeff(),
              kFiniteDifferenceTolerance);
  }
}

TEST(BoxSurface, MatchesTheDistanceToTheNearestFaceOrBoxPoint) {
  const BoxSurface box{Vec3(0.5, 0.2, 0.3)};
  std::mt19937 rng(2);
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p = randomPoint(rng, 1.0);
    const Vec3 q = p.cwiseAbs() - box.halfExtents;
    double expected;
    if ((q.array() <= 0.0).all()) {
      expected = q.maxCoeff();  // minus the distance to the nearest face plane
    } else {
      const Vec3 nearest = p.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
      expected = (p - nearest).norm();
    }
    EXPECT_NEAR(box.phi(p), expected, 1e-15) << p.transpose();
    // Away from the medial planes (two faces nearly equally near), the gradient is smooth.
    Vec3 sorted = q;
    std::sort(sorted.data(), sorted.data() + 3);
    if (sorted[2] < 0.0 && sorted[2] - sorted[1] < 1e-3) continue;
    EXPECT_NEAR(box.gradient(p).norm(), 1.0, 1e-12);
    EXPECT_LT((box.gradient(p) - centralDifference(box, p)).cwiseAbs().maxCoeff(),
              kFiniteDifferenceTolerance)
        << p.transpose();
  }
}

TEST(EllipsoidSurface, SignIsTheSeedsAndExactOnTheAxesAndSurface) {
  const EllipsoidSurface e{Vec3(1.0, 0.5, 0.25)};
  std::mt19937 rng(3);
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p = randomPoint(rng, 1.5);
    const double seed = p.cwiseQuotient(e.radii).squaredNorm() - 1.0;  // seed 000's function
    EXPECT_EQ(e.phi(p) < 0.0, seed < 0.0) << p.transpose();
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (double d : {-0.1, 0.0, 0.4, 3.0}) {
      Vec3 p = Vec3::Zero();
      p[axis] = e.radii[axis] + d;
      EXPECT_NEAR(e.phi(p), d, 1e-14) << "axis " << axis;
    }
  }
  // With equal radii it is the sphere's exact distance.
  const EllipsoidSurface round{Vec3::Constant(0.6)};
  EXPECT_NEAR(round.phi(Vec3(0.3, -0.8, 0.2)), Vec3(0.3, -0.8, 0.2).norm() - 0.6, 1e-15);
}

TEST(EllipsoidSurface, FirstOrderDistanceErrorIsBoundedNearTheSurface) {
  const Vec3 radii(1.0, 0.5, 0.25);
  const EllipsoidSurface e{radii};
  std::mt19937 rng(4);
  double worstOutside = 0.0, worstInside = 0.0;
  for (int n = 0; n < 20000; ++n) {
    const Vec3 p = randomPoint(rng, 1.6);
    const double exact = trueEllipsoidDistance(radii, p);
    if (exact >= 0.05 && exact <= 0.5) {
      worstOutside = std::max(worstOutside, std::abs(e.phi(p) - exact) / exact);
    } else if (exact <= -0.02 && exact >= -0.1) {
      worstInside = std::max(worstInside, std::abs(e.phi(p) - exact) / -exact);
    }
  }
  RecordProperty("worst_relative_error_outside", std::to_string(worstOutside));
  RecordProperty("worst_relative_error_inside", std::to_string(worstInside));
  std::printf("ellipsoid (1, 0.5, 0.25): worst relative error %.4f outside (0.05..0.5 m), %.4f "
              "inside (0.02..0.1 m deep)\n", worstOutside, worstInside);
  // Measured 0.364 and 0.287 (20000 points, seed 4): the approximation's documented error.
  EXPECT_LT(worstOutside, 0.40);
  EXPECT_LT(worstInside, 0.32);
}

TEST(EllipsoidSurface, GradientMatchesFiniteDifferences) {
  const EllipsoidSurface e{Vec3(1.0, 0.5, 0.25)};
  std::mt19937 rng(5);
  for (int n = 0; n < 1000; ++n) {
    const Vec3 p = randomPoint(rng, 1.5);
    if (p.norm() < 0.05) continue;
    EXPECT_LT((e.gradient(p) - centralDifference(e, p)).cwiseAbs().maxCoeff(), 1e-5) << p.transpose();
  }
}

}  // namespace
}  // namespace rbsim
