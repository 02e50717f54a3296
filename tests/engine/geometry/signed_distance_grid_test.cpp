// geometry/signed_distance_grid: grid phi of sphere and box meshes against their analytic signed
// distances, |grad phi| ~ 1, the sign at every grid point of a torus and of a hollow sphere,
// exact trilinear interpolation of linear fields, determinism, and bad input.
#include "rbsim/geometry/signed_distance_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "geometry/implicit_surface.h"
#include "rbsim/geometry/mesh_generators.h"
#include "geometry/surface_samples.h"

namespace rbsim {
namespace {

// Worst |grid - exact| [cells] over the grid points, split at `band` cells from the surface,
// leaving out those where `skip` is true (near the medial axis, where first-order fast marching
// is least accurate).
struct GridError {
  double nearCells = 0.0, farCells = 0.0;
};
template <class Exact, class Skip>
GridError gridPointError(const SignedDistanceGrid& g, const Exact& exact, double band, const Skip& skip) {
  GridError e;
  const double h = g.cellSize();
  for (int k = 0; k < g.dims().z(); ++k) {
    for (int j = 0; j < g.dims().y(); ++j) {
      for (int i = 0; i < g.dims().x(); ++i) {
        if (skip(g.point(i, j, k))) continue;
        const double truth = exact(g.point(i, j, k));
        const double err = std::abs(g.value(i, j, k) - truth) / h;
        (std::abs(truth) <= band * h ? e.nearCells : e.farCells) =
            std::max(std::abs(truth) <= band * h ? e.nearCells : e.farCells, err);
      }
    }
  }
  return e;
}

Mesh reversed(Mesh m) {
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

Mesh hollowSphere(double outer, double inner) {
  Mesh m = makeUvSphere(outer, 48, 24);
  const Mesh cavity = reversed(makeUvSphere(inner, 32, 16));
  const std::uint32_t offset = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), cavity.vertices.begin(), cavity.vertices.end());
  for (Triangle t : cavity.triangles) {
    for (auto& v : t) v += offset;
    m.triangles.push_back(t);
  }
  m.name = "hollow sphere";
  return m;
}

TEST(SignedDistanceGrid, SphereMeshMatchesTheAnalyticDistance) {
  const double radius = 1.0;
  const Mesh mesh = makeUvSphere(radius, 96, 48);  // faceting error R (1 - cos(pi / 48)) = 2e-3 m
  const SignedDistanceGrid g = SignedDistanceGrid::build(mesh, {32, 3, 2});
  const SphereSurface sphere{radius};
  const auto exact = [&](const Vec3& p) { return sphere.phi(p); };
  const GridError e = gridPointError(g, exact, 2.0, [](const Vec3& p) { return p.norm() < 0.3; });
  const GridError all = gridPointError(g, exact, 2.0, [](const Vec3&) { return false; });
  std::printf("sphere R=1 res 32 (h=%.4f m): max error %.3f cells within 2 cells, %.3f beyond "
              "(r >= 0.3 m), %.3f with the centre; %zu exact, %zu marched, %d regions\n",
              g.cellSize(), e.nearCells, e.farCells, all.farCells, g.stats().exactPoints,
              g.stats().marchedPoints, g.stats().regions);
  EXPECT_LT(e.nearCells, 0.05);    // exact distance to the facets: only the faceting error 0.03 h
  EXPECT_LT(e.farCells, 0.6);      // first-order fast marching: measured 0.51 h
  EXPECT_LT(all.farCells, 1.25);   // where the fronts converge at the centre: measured 1.13 h
  EXPECT_EQ(g.stats().regions, 2);
  EXPECT_EQ(g.stats().exactPoints + g.stats().marchedPoints, g.pointCount());
}

TEST(SignedDistanceGrid, BoxMeshMatchesTheAnalyticDistance) {
  const Vec3 extents(1.0, 0.62, 0.81);
  const SignedDistanceGrid g = SignedDistanceGrid::build(makeBox(extents), {32, 3, 2});
  const BoxSurface box{0.5 * extents};
  const GridError e = gridPointError(g, [&](const Vec3& p) { return box.phi(p); }, 2.0,
                                     [](const Vec3&) { return false; });
  std::printf("box res 32: max error %.3f cells within 2 cells, %.3f beyond\n", e.nearCells,
              e.farCells);
  EXPECT_LT(e.nearCells, 1e-12);  // the mesh is the box exactly
  EXPECT_LT(e.farCells, 0.7);     // fast marching, medial planes included: measured 0.62 h
  // Interpolated between grid points near the surface.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-0.7, 0.7);
  double worst = 0.0;
  for (int n = 0; n < 5000; ++n) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (std::abs(box.phi(p)) > 0.1) continue;
    worst = std::max(worst, std::abs(g.phi(p) - box.phi(p)) / g.cellSize());
  }
  std::printf("box res 32: max interpolated error %.3f cells within 0.1 m\n", worst);
  EXPECT_LT(worst, 0.5);
}

TEST(SignedDistanceGrid, GradientHasUnitLengthAwayFromTheMedialAxis) {
  const SignedDistanceGrid g = SignedDistanceGrid::build(makeUvSphere(1.0, 96, 48), {32, 3, 2});
  std::mt19937 rng(32);
  // Inside the grid's box (beyond it phi is extended, not interpolated).
  const double half = 0.5 * g.cellSize() * (g.dims().x() - 1);
  std::uniform_real_distribution<double> u(-half, half);
  double worst = 0.0, worstAngle = 0.0;
  for (int n = 0; n < 5000; ++n) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (p.norm() < 0.4) continue;  // the medial axis of a sphere is its centre
    worst = std::max(worst, std::abs(g.gradient(p).norm() - 1.0));
    worstAngle = std::max(worstAngle, std::acos(std::min(1.0, g.normal(p).dot(p.normalized()))));
  }
  std::printf("sphere res 32: max | |grad phi| - 1 | %.3f, max normal angle %.2f deg\n", worst,
              worstAngle * 180.0 / kPi);
  EXPECT_LT(worst, 0.15);  // measured 0.096
  EXPECT_LT(worstAngle, 10.0 * kPi / 180.0);  // measured 7.6 degrees
  // Outside the grid's box: the distance to the box plus phi there, gradient pointing away.
  const Vec3 far(10.0, 0.0, 0.0);
  EXPECT_NEAR(g.phi(far), 9.0, 0.02);
  EXPECT_EQ(g.gradient(far).x(), 1.0);
  EXPECT_GT(g.normal(far).x(), 0.99);
}

TEST(SignedDistanceGrid, TorusSignIsRightAtEveryGridPoint) {
  const double major = 1.0, minor = 0.3;
  const Mesh mesh = makeTorus(major, minor, 64, 24);
  const SignedDistanceGrid g = SignedDistanceGrid::build(mesh, {40, 3, 2});
  // The facets lie inside the exact torus by at most the sagitta of each direction.
  const double faceting = minor * (1 - std::cos(kPi / 24)) + (major + minor) * (1 - std::cos(kPi / 64));
  int checked = 0;
  for (int k = 0; k < g.dims().z(); ++k) {
    for (int j = 0; j < g.dims().y(); ++j) {
      for (int i = 0; i < g.dims().x(); ++i) {
        const Vec3 p = g.point(i, j, k);
        const double exact = std::hypot(std::hypot(p.x(), p.z()) - major, p.y()) - minor;
        if (std::abs(exact) <= faceting) continue;
        ++checked;
        ASSERT_EQ(g.value(i, j, k) < 0.0, exact < 0.0) << p.transpose();
      }
    }
  }
  EXPECT_GT(checked, 0.99 * g.pointCount());
  EXPECT_EQ(g.stats().regions, 2);
}

TEST(SignedDistanceGrid, HollowSphereHasThreeRegionsAndAnOutsideCavity) {
  const Mesh mesh = hollowSphere(1.0, 0.6);
  const SignedDistanceGrid g = SignedDistanceGrid::build(mesh, {32, 3, 2});
  EXPECT_EQ(g.stats().regions, 3);
  const double faceting = 1.0 * (1 - std::cos(kPi / 24));
  for (int k = 0; k < g.dims().z(); ++k) {
    for (int j = 0; j < g.dims().y(); ++j) {
      for (int i = 0; i < g.dims().x(); ++i) {
        const double r = g.point(i, j, k).norm();
        if (std::abs(r - 1.0) <= faceting || std::abs(r - 0.6) <= faceting) continue;
        const bool solid = r > 0.6 && r < 1.0;
        ASSERT_EQ(g.value(i, j, k) < 0.0, solid) << "r = " << r;
      }
    }
  }
  // The cavity's centre is 0.6 m from the wall; fronts converging there carry fast marching's
  // largest error (measured 0.98 h, as at the solid sphere's centre).
  EXPECT_NEAR(g.phi(Vec3::Zero()), 0.6, 1.25 * g.cellSize());
}

TEST(SignedDistanceGrid, TrilinearInterpolationIsExactForLinearFields) {
  GridLattice shape;
  shape.origin = Vec3(-1.0, 0.5, 2.0);
  shape.cellSize = 0.25;
  shape.dims = Vec3i(5, 7, 4);
  const Vec3 slope(0.3, -1.2, 0.7);
  const auto field = [&](const Vec3& p) { return 0.4 + slope.dot(p); };
  std::vector<double> values(shape.pointCount());
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 5; ++i) values[shape.index(i, j, k)] = field(shape.point(i, j, k));
  const SignedDistanceGrid g = SignedDistanceGrid::fromValues(shape, values);
  std::mt19937 rng(33);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 1000; ++n) {
    const Vec3 p = shape.origin + Vec3(u(rng) * 1.0, u(rng) * 1.5, u(rng) * 0.75);
    EXPECT_NEAR(g.phi(p), field(p), 1e-13);
    EXPECT_LT((g.gradient(p) - slope).cwiseAbs().maxCoeff(), 1e-12);
  }
  // Outside: 1 m beyond the +x face, the distance plus the value on the face.
  const Vec3 face = shape.origin + Vec3(1.0, 0.7, 0.3);
  EXPECT_NEAR(g.phi(face + Vec3(1.0, 0, 0)), 1.0 + field(face), 1e-13);
  EXPECT_NEAR(g.gradient(face + Vec3(1.0, 0, 0)).x(), 1.0, 1e-15);
  EXPECT_NEAR(g.gradient(face + Vec3(1.0, 0, 0)).y(), slope.y(), 1e-12);
  EXPECT_THROW(SignedDistanceGrid::fromValues(shape, std::vector<double>(3)), std::invalid_argument);
}

TEST(SignedDistanceGrid, BuildIsDeterministic) {
  const Mesh mesh = makeBowl(1.0, 0.15, 32, 8);
  const SignedDistanceGrid a = SignedDistanceGrid::build(mesh, {24, 2, 2});
  const SignedDistanceGrid b = SignedDistanceGrid::build(mesh, {24, 2, 2});
  ASSERT_EQ(a.dims(), b.dims());
  for (int k = 0; k < a.dims().z(); ++k)
    for (int j = 0; j < a.dims().y(); ++j)
      for (int i = 0; i < a.dims().x(); ++i) ASSERT_EQ(a.value(i, j, k), b.value(i, j, k));
  EXPECT_LT(a.phi(Vec3(0.0, -0.925, 0.0)), 0.0) << "inside the bowl's wall";
  EXPECT_GT(a.phi(Vec3(0.0, -0.5, 0.0)), 0.0) << "in the bowl's hollow";
}

void expectBuildThrows(const Mesh& mesh, const SdfGridOptions& options, const std::string& needle) {
  try {
    SignedDistanceGrid::build(mesh, options);
    FAIL() << "expected std::invalid_argument mentioning '" << needle << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(SignedDistanceGrid, BadMeshesAndOptionsThrow) {
  Mesh open = makeBox(Vec3::Ones());
  open.triangles.pop_back();
  expectBuildThrows(open, {}, "exactly twice");
  Mesh flipped = makeBox(Vec3::Ones());
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  expectBuildThrows(flipped, {}, "inconsistent winding");
  expectBuildThrows(reversed(makeBox(Vec3::Ones())), {}, "counter-clockwise seen from outside");
  Mesh degenerate = makeBox(Vec3::Ones());
  degenerate.vertices[2] = degenerate.vertices[0];  // triangles (0, 2, 1) and (0, 3, 2) collapse
  expectBuildThrows(degenerate, {}, "2 degenerate (zero-area)");
  Mesh notFinite = makeBox(Vec3::Ones());
  notFinite.vertices[2].x() = std::nan("");
  expectBuildThrows(notFinite, {}, "not finite");
  expectBuildThrows(makeBox(Vec3::Ones()), {3, 3, 2}, "resolution");
  expectBuildThrows(makeBox(Vec3::Ones()), {16, 0, 2}, "paddingCells");
  expectBuildThrows(makeBox(Vec3::Ones()), {16, 3, 0}, "exactBandCells");
}


TEST(SignedDistanceGrid, GridsOverBudgetAreRefusedBeforeAllocating) {
  const Mesh cube = makeBox(Vec3::Ones());
  EXPECT_EQ(sdfBudgetProblem(cube, {32, 3, 2}), "");
  const std::string problem = sdfBudgetProblem(cube, {1024, 3, 2});
  EXPECT_NE(problem.find("resolution 1024 lays a 1031 x 1031 x 1031 grid over mesh 'box' (1.1e+09 points"),
            std::string::npos) << problem;
  EXPECT_NE(problem.find("the limit is 1.6e+07 points"), std::string::npos) << problem;
  expectBuildThrows(cube, {1024, 3, 2}, "the limit is 1.6e+07 points");
  // The documented maximum resolution fits a slender mesh.
  EXPECT_EQ(sdfBudgetProblem(makeBox(Vec3(1.0, 0.01, 0.01)), {1024, 3, 2}), "");
  // The largest a cube-like mesh gets is about 240.
  EXPECT_EQ(sdfBudgetProblem(cube, {240, 3, 2}), "");
  EXPECT_NE(sdfBudgetProblem(cube, {260, 3, 2}), "");
}

TEST(SurfaceSamples, TooManySamplesAreRefusedBeforeAnyIsMade) {
  const Mesh cube = makeBox(Vec3::Ones());
  EXPECT_EQ(surfaceSampleBudgetProblem(cube, 0.01), "");
  EXPECT_NEAR(surfaceSampleEstimate(cube, 0.01), double(surfaceSamples(cube, 0.01).size()), 0.05 * 1.2e5)
      << "an upper bound: edges are counted once per triangle";
  const std::string problem = surfaceSampleBudgetProblem(cube, 1e-4);
  EXPECT_NE(problem.find("spacing 0.0001 m on mesh 'box' (area 6 m^2) needs up to 1.2e+09 surface samples"), std::string::npos) << problem;
  EXPECT_NE(problem.find("the limit is 4e+06 samples"), std::string::npos) << problem;
  EXPECT_THROW(surfaceSamples(cube, 1e-300), std::invalid_argument);
  // A tiny spacing on a tiny mesh is a small count: fine.
  EXPECT_EQ(surfaceSampleBudgetProblem(makeBox(Vec3::Constant(1e-6)), 1e-8), "");
}

}  // namespace
}  // namespace rbsim
