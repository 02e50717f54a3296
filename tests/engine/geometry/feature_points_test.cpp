// geometry/feature_points: dual contouring's points lie on the exact surface, and a box's are
// sharp: its eight corners are among them exactly and its edges are lined with points, at a
// resolution whose grid hits none of them, where a marching mesh bevels them all.
#include <cmath>

#include <gtest/gtest.h>

#include "geometry/feature_points.h"
#include "geometry/implicit_primitives.h"
#include "geometry/implicit_surface.h"

namespace rbsim {
namespace {

// A grid of `cells` cells across [-1, 1]^3 shifted by an irrational fraction of a cell, so that no
// grid point or edge meets the solids' corners.
SignedDistanceGrid gridOf(const ExactField& field, int cells) {
  GridLattice lattice;
  lattice.cellSize = 2.4 / cells;
  lattice.dims = Vec3i::Constant(cells + 1);
  lattice.origin = Vec3::Constant(-1.2 + 0.3819660113 * lattice.cellSize);
  std::vector<double> values(lattice.pointCount());
  for (int k = 0; k < lattice.dims.z(); ++k) {
    for (int j = 0; j < lattice.dims.y(); ++j) {
      for (int i = 0; i < lattice.dims.x(); ++i) values[lattice.index(i, j, k)] = field.phi(lattice.point(i, j, k));
    }
  }
  return SignedDistanceGrid::fromValues(lattice, values);
}

ExactField fieldOf(const BoxSurface& box) {
  return {[box](const Vec3& p) { return box.phi(p); }, [box](const Vec3& p) { return box.gradient(p); }};
}

TEST(FeaturePoints, ABoxsCornersAndEdgesAreSharpAtAnyResolution) {
  const BoxSurface box{Vec3(0.7, 0.45, 0.3)};
  const ExactField field = fieldOf(box);
  for (int cells : {8, 16, 64}) {
    const SignedDistanceGrid grid = gridOf(field, cells);
    const std::vector<Vec3> points = featurePoints(grid, field);
    ASSERT_FALSE(points.empty());
    for (const Vec3& p : points) ASSERT_NEAR(box.phi(p), 0.0, 1e-9) << cells << " cells at " << p.transpose();
    // Every corner is a point, to rounding.
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 c((corner & 1) ? 0.7 : -0.7, (corner & 2) ? 0.45 : -0.45, (corner & 4) ? 0.3 : -0.3);
      double nearest = 1e9;
      for (const Vec3& p : points) nearest = std::min(nearest, (p - c).norm());
      EXPECT_LT(nearest, 1e-9) << cells << " cells, corner " << c.transpose();
    }
    // Along the edge x = 0.7, y = 0.45 there is a point on the edge in every cell it crosses.
    int onEdge = 0;
    for (const Vec3& p : points) {
      if (std::abs(p.x() - 0.7) < 1e-9 && std::abs(p.y() - 0.45) < 1e-9) ++onEdge;
    }
    EXPECT_GE(onEdge, static_cast<int>(std::floor(0.6 / grid.cellSize())) + 1) << cells << " cells";
  }
}

TEST(FeaturePoints, ASphereIsCoveredAtTheCellSpacing) {
  const SphereSurface sphere{0.8};
  const ExactField field{[sphere](const Vec3& p) { return sphere.phi(p); }, [sphere](const Vec3& p) { return sphere.gradient(p); }};
  const SignedDistanceGrid grid = gridOf(field, 24);
  const std::vector<Vec3> points = featurePoints(grid, field);
  for (const Vec3& p : points) ASSERT_NEAR(sphere.phi(p), 0.0, 1e-12);
  // Every direction finds a point within a cell's diagonal of its surface point.
  double worst = 0.0;
  for (int n = 0; n < 500; ++n) {
    const double z = -1.0 + (n + 0.5) / 250.0, angle = n * 2.399963229728653;  // golden angle spiral
    const Vec3 s = 0.8 * Vec3(std::sqrt(1.0 - z * z) * std::cos(angle), z, std::sqrt(1.0 - z * z) * std::sin(angle));
    double nearest = 1e9;
    for (const Vec3& p : points) nearest = std::min(nearest, (p - s).norm());
    worst = std::max(worst, nearest);
  }
  EXPECT_LT(worst, std::sqrt(3.0) * grid.cellSize());
}

}  // namespace
}  // namespace rbsim
