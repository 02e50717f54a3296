#include "shapes/implicit_shape.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "geometry/feature_points.h"

namespace rbsim {

namespace {

double secondsSince(std::clock_t start) { return double(std::clock() - start) / CLOCKS_PER_SEC; }

void requireResolution(const ImplicitShape& shape) {
  if (shape.resolution < kMinSdfResolution || shape.resolution > kMaxSdfResolution) {
    throw std::invalid_argument("implicit shape: resolution is " + std::to_string(shape.resolution) + ", expected " +
                                std::to_string(kMinSdfResolution) + " to " + std::to_string(kMaxSdfResolution));
  }
}

std::vector<double> sample(const ImplicitShape& shape, const GridLattice& grid, const Mat3& axes, const Vec3& centre,
                           const char* stage) {
  if (shape.budget) shape.budget->charge(grid.dims.cast<double>().prod(), stage);
  const ImplicitFunction& f = *shape.function;
  std::vector<double> values(grid.pointCount());
  for (int k = 0; k < grid.dims.z(); ++k) {
    for (int j = 0; j < grid.dims.y(); ++j) {
      for (int i = 0; i < grid.dims.x(); ++i) values[grid.index(i, j, k)] = f.phi(axes * grid.point(i, j, k) + centre);
    }
  }
  return values;
}

}  // namespace

void ImplicitBudget::spend(double evaluations, const char* stage, std::size_t triangles) {
  spent_ += evaluations;
  if (!(spent_ > limit_)) return;
  std::ostringstream problem;
  problem << std::setprecision(3) << "loading it (a tree of " << primitives_ << (primitives_ == 1.0 ? " primitive" : " primitives")
          << ") passed its budget of " << limit_ << " primitive evaluations (~" << limit_ * kImplicitSecondsPerEvaluation
          << " s) at " << stage;
  if (triangles > 0) problem << " of " << triangles << " triangles";
  throw ImplicitBudgetExceeded(problem.str());
}

GridLattice implicitGridLattice(const ImplicitShape& shape) {
  const ImplicitBounds b = shape.function->bounds();
  GridLattice grid;
  if (b.empty()) return grid;
  grid.cellSize = (b.hi - b.lo).maxCoeff() / shape.resolution;
  for (int axis = 0; axis < 3; ++axis) {
    double cells = std::ceil((b.hi[axis] - b.lo[axis]) / grid.cellSize - 1e-9);
    if (!(cells >= 1.0)) cells = 1.0;
    grid.dims[axis] = static_cast<int>(std::min(cells, double(shape.resolution))) + 2 * kImplicitPaddingCells + 1;
  }
  grid.origin = 0.5 * (b.lo + b.hi) - 0.5 * grid.cellSize * (grid.dims - Vec3i::Ones()).cast<double>();
  return grid;
}

std::string implicitBudgetProblem(const ImplicitShape& shape) {
  const GridLattice grid = implicitGridLattice(shape);
  const double points = grid.dims.cast<double>().prod();
  const double evaluations = points * shape.function->primitiveCount();
  std::ostringstream problem;
  problem << std::setprecision(3) << "resolution " << shape.resolution << " lays a " << grid.dims.x() << " x "
          << grid.dims.y() << " x " << grid.dims.z() << " grid (" << points << " points, ~"
          << std::setprecision(2) << points * kSdfBytesPerPoint / 1e9 << " GB)";
  if (points > kMaxSdfGridPoints) {
    problem << std::setprecision(3) << "; the limit is " << kMaxSdfGridPoints << " points (~"
            << kMaxSdfGridPoints * kSdfBytesPerPoint / 1e9 << " GB)";
    return problem.str();
  }
  // The body's grid is laid over the mesh at the same resolution: about as many points again.
  if (2.0 * evaluations > kMaxImplicitEvaluations) {
    problem << std::setprecision(3) << ", sampled twice, of " << shape.function->primitiveCount() << " primitives: "
            << 2.0 * evaluations << " primitive evaluations (~" << 2.0 * evaluations * kImplicitSecondsPerEvaluation
            << " s); the limit is " << kMaxImplicitEvaluations << " (~"
            << kMaxImplicitEvaluations * kImplicitSecondsPerEvaluation << " s)";
    return problem.str();
  }
  return "";
}

ImplicitMeshing meshImplicitShape(const ImplicitShape& shape) {
  requireResolution(shape);
  if (shape.function->bounds().empty()) {
    throw std::invalid_argument("the solid is empty: its operands' bounds do not overlap");
  }
  const std::string overBudget = implicitBudgetProblem(shape);
  if (!overBudget.empty()) throw std::invalid_argument(overBudget);
  ImplicitMeshing out;
  out.grid = implicitGridLattice(shape);
  std::clock_t start = std::clock();
  const std::vector<double> values = sample(shape, out.grid, Mat3::Identity(), Vec3::Zero(), "the meshing grid");
  out.sampleSeconds = secondsSince(start);
  start = std::clock();
  out.mesh = marchingTetrahedra(out.grid, values, &out.stats);
  out.meshSeconds = secondsSince(start);
  if (out.mesh.triangles.empty()) {
    // Every point lies within half a cell's diagonal of a grid point, and phi is at most the
    // distance to the solid (csg.h): if every grid point has phi above that, there is no solid;
    // otherwise it may be one thinner or smaller than a cell, which the grid passes between.
    const double nearest = *std::min_element(values.begin(), values.end());
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * out.grid.cellSize;
    std::ostringstream problem;
    problem << std::setprecision(3);
    if (nearest <= halfDiagonal) {
      problem << "no point of the " << out.grid.dims.x() << " x " << out.grid.dims.y() << " x " << out.grid.dims.z()
              << " grid is inside, but its surface passes " << nearest << " m from one: the solid is thinner or smaller "
              << "than a grid cell (" << out.grid.cellSize << " m); raise the shape's resolution";
    } else {
      problem << "the solid is empty: no point of the " << out.grid.dims.x() << " x " << out.grid.dims.y() << " x "
              << out.grid.dims.z() << " grid (cell " << out.grid.cellSize << " m) is inside (phi < 0), nor within a cell "
              << "of the surface, so it has no volume";
    }
    throw std::invalid_argument(problem.str());
  }
  if (shape.budget) shape.budget->chargeMesh(out.mesh.triangles.size());
  if (out.mesh.triangles.size() > kMaxMeshTriangles || out.mesh.vertices.size() > kMaxMeshVertices) {
    std::ostringstream problem;
    problem << "resolution " << shape.resolution << " meshes the surface into " << out.mesh.triangles.size()
            << " triangles and " << out.mesh.vertices.size() << " vertices; the limit is " << kMaxMeshTriangles
            << " triangles and " << kMaxMeshVertices << " vertices (as for a mesh file)";
    throw std::invalid_argument(problem.str());
  }
  return out;
}

SignedDistanceGrid implicitBodyGrid(const ImplicitShape& shape, const Mesh& bodyMesh, const Mat3& axes,
                                    const Vec3& centre) {
  requireResolution(shape);
  SdfGridOptions options;
  options.resolution = shape.resolution;
  const GridLattice grid = sdfGridLattice(bodyMesh, options);
  if (grid.dims.cast<double>().prod() > kMaxSdfGridPoints) {
    throw std::invalid_argument("implicit shape: the body's grid of resolution " + std::to_string(shape.resolution) +
                                " exceeds " + std::to_string(static_cast<long long>(kMaxSdfGridPoints)) + " points");
  }
  return SignedDistanceGrid::fromValues(grid, sample(shape, grid, axes, centre, "the body's grid"));
}

Vec3 ImplicitSolid::gradient(const Vec3& p) const {
  Vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 step = gradientStep * Vec3::Unit(axis);
    g[axis] = (phi(p + step) - phi(p - step)) / (2.0 * gradientStep);
  }
  return g;
}

Vec3 ImplicitSolid::supportNear(const Vec3& start, const Vec3& d, double cellSize) const {
  const ExactField field{[&](const Vec3& p) { return phi(p); }, [&](const Vec3& p) { return gradient(p); }};
  Vec3 best = start, x = start;
  Vec3 normal = gradient(x).normalized();
  double radius = cellSize;  // the patch's radius of curvature, until two normals show it
  for (int step = 0; step < kSupportSteps; ++step) {
    const Vec3 tangent = d - normal * normal.dot(d);
    if (!(tangent.norm() > kSupportAngle)) break;
    // On a sphere of radius rho through x with normal n there, the point along d is x + rho (d - n).
    const Vec3 next = projectOntoSurface(x + radius * (d - normal), field, kCrossingTolerance * cellSize);
    if (!((next - start).norm() <= 2.0 * cellSize)) break;  // left the patch: another feature
    if (!(std::abs(phi(next)) <= kSupportOnSurface * cellSize)) break;  // the projection did not converge
    const Vec3 nextNormal = gradient(next).normalized();
    const double turned = (nextNormal - normal).norm();
    if (!(turned > 0.0)) break;  // flat: every point of the face is as far along d
    radius = (next - x).norm() / turned;
    x = next;
    normal = nextNormal;
    if (d.dot(x) > d.dot(best)) best = x;
  }
  return best;
}

ImplicitSolid implicitSolidOf(const ImplicitShape& shape, const Mat3& axes, const Vec3& centre) {
  const ImplicitBounds b = shape.function->bounds();
  const double extent = b.empty() ? 1.0 : (b.hi - b.lo).maxCoeff();
  return ImplicitSolid{shape.function, axes, centre, kImplicitGradientRelStep * extent};
}

ExactField implicitField(const ImplicitSolid& solid, ImplicitBudget* budget) {
  constexpr const char* stage = "the surface samples' crossings and corners";
  return ExactField{[&solid, budget](const Vec3& p) {
                      if (budget) budget->charge(1.0, stage);
                      return solid.phi(p);
                    },
                    [&solid, budget](const Vec3& p) {
                      if (budget) budget->charge(6.0, stage);  // central differences
                      return solid.gradient(p);
                    }};
}

std::vector<Vec3> implicitSurfaceSamples(const ImplicitSolid& solid, const SignedDistanceGrid& bodyGrid,
                                         ImplicitBudget* budget) {
  return featurePoints(bodyGrid, implicitField(solid, budget));
}

}  // namespace rbsim
