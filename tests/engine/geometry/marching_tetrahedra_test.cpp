// geometry/marching_tetrahedra: the mesh of a sampled function is closed, consistently wound
// outwards and free of zero-area triangles, including when the surface runs through grid points
// (a box's faces on grid planes), and it encloses the solid's volume to the grid's accuracy.
#include "geometry/marching_tetrahedra.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "geometry/implicit_primitives.h"
#include "geometry/implicit_surface.h"
#include "rbsim/mass/mass_properties.h"

namespace rbsim {
namespace {

// A cube of `points` per axis, cells of h [m], centred on the origin, with phi sampled.
std::pair<GridLattice, std::vector<double>> sampled(const std::function<double(const Vec3&)>& phi, int points, double h) {
  GridLattice grid;
  grid.cellSize = h;
  grid.dims = Vec3i::Constant(points);
  grid.origin = Vec3::Constant(-0.5 * h * (points - 1));
  std::vector<double> values(grid.pointCount());
  for (int k = 0; k < points; ++k) {
    for (int j = 0; j < points; ++j) {
      for (int i = 0; i < points; ++i) values[grid.index(i, j, k)] = phi(grid.point(i, j, k));
    }
  }
  return {grid, values};
}

void expectSolidMesh(const Mesh& mesh) {
  const MeshCheck check = checkMesh(mesh);
  EXPECT_TRUE(check.closed) << check.problem;
  EXPECT_TRUE(check.consistentlyOriented) << check.problem;
  EXPECT_EQ(check.degenerateTriangles, 0u) << check.problem;
}

TEST(MarchingTetrahedra, SphereIsClosedOutwardAndHoldsItsVolume) {
  const SphereSurface s{0.5};
  double lastError = INFINITY;
  for (const int points : {17, 33, 65}) {
    const auto [grid, values] = sampled([&](const Vec3& p) { return s.phi(p); }, points, 1.2 / (points - 1));
    const Mesh mesh = marchingTetrahedra(grid, values);
    expectSolidMesh(mesh);
    const MassProperties m = polyhedralMassProperties(mesh, 1.0);
    const double exact = 4.0 / 3.0 * M_PI * 0.125;
    const double error = std::abs(m.volume - exact) / exact;
    EXPECT_GT(m.volume, 0.0);  // positive: the triangles face out
    EXPECT_LT(error, 0.02) << points;
    EXPECT_LT(error, 0.5 * lastError) << points;  // second order: about a quarter per halved cell
    EXPECT_LT(m.centerOfMass.norm(), 1e-3);
    lastError = error;
  }
}

TEST(MarchingTetrahedra, FacesOnGridPlanesGiveNoZeroAreaTriangles) {
  // Half extents of whole cells: every face lies on a plane of grid points where phi = 0.
  const double h = 0.05;
  const BoxSurface box{Vec3(0.2, 0.3, 0.1)};
  const auto [grid, values] = sampled([&](const Vec3& p) { return box.phi(p); }, 21, h);
  MarchingStats stats;
  const Mesh mesh = marchingTetrahedra(grid, values, &stats);
  expectSolidMesh(mesh);
  EXPECT_GT(stats.snappedVertices, 0u);  // the case this test is for did occur
  // The faces lie on the grid's planes and come out exact: the mesh's box is the box's. Across
  // an edge the linear interpolant may cut a chamfer of at most h^2 / 2 of section (where the
  // cells' diagonal runs along the edge instead of across it); nothing is added outside.
  EXPECT_NEAR((mesh.boundsMax() - box.halfExtents).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  EXPECT_NEAR((mesh.boundsMin() + box.halfExtents).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  const double volume = polyhedralMassProperties(mesh, 1.0).volume, exact = 8.0 * box.halfExtents.prod();
  const double edges = 8.0 * box.halfExtents.sum();  // [m], the twelve edges' length
  EXPECT_LE(volume, exact + 1e-12);
  EXPECT_GE(volume, exact - edges * 0.5 * h * h);
}

TEST(MarchingTetrahedra, ATorusHasTheGenusOfATorus) {
  const TorusSurface t{0.4, 0.15};
  const auto [grid, values] = sampled([&](const Vec3& p) { return t.phi(p); }, 49, 1.2 / 48);
  const Mesh mesh = marchingTetrahedra(grid, values);
  expectSolidMesh(mesh);
  // Euler characteristic V - E + F = 2 - 2 g with E = 3 F / 2 for a closed mesh: 0 for a torus.
  const long long v = static_cast<long long>(mesh.vertices.size()), f = static_cast<long long>(mesh.triangles.size());
  EXPECT_EQ(v - 3 * f / 2 + f, 0);
}

TEST(MarchingTetrahedra, NoInsidePointGivesAnEmptyMeshAndBadValuesAreRefused) {
  const auto [grid, values] = sampled([](const Vec3& p) { return p.norm() + 0.1; }, 5, 0.1);
  MarchingStats stats;
  EXPECT_TRUE(marchingTetrahedra(grid, values, &stats).triangles.empty());
  EXPECT_EQ(stats.insidePoints, 0u);
  std::vector<double> wrong = values;
  wrong.pop_back();
  EXPECT_THROW(marchingTetrahedra(grid, wrong), std::invalid_argument);
  wrong = values;
  wrong[3] = NAN;
  EXPECT_THROW(marchingTetrahedra(grid, wrong), std::invalid_argument);
}

}  // namespace
}  // namespace rbsim
