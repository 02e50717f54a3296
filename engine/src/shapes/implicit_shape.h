#pragma once
// A body whose solid is an analytic implicit function or a CSG tree of them (geometry/csg.h).
// The exact function is sampled on a grid twice: over its bounds in the file frame, where marching
// tetrahedra mesh it for drawing and mass properties (geometry/marching_tetrahedra.h), and over
// the mesh in the body frame, where the samples are the body's signed distance grid (seed 000
// "Discrete Implicit Surfaces": "store values of the function at grid points"). The grid only
// finds candidates: contact points, normals and depths come from the exact function
// (ImplicitSolid below, collision/body_solid.h), and the body's surface samples keep its sharp
// edges and corners (geometry/feature_points.h).
#include <memory>
#include <stdexcept>
#include <string>

#include <vector>

#include "geometry/csg.h"
#include "geometry/feature_points.h"
#include "rbsim/geometry/grid_lattice.h"
#include "geometry/marching_tetrahedra.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/geometry/signed_distance_grid.h"

namespace rbsim {

// Cells along the longest side of the function's bounds when the scene gives no "resolution":
// a 0.5 m cup's wall of 0.06 m is then ~3 cells thick.
inline constexpr int kDefaultImplicitResolution = 48;  // [1]
// Points outside the bounds on each side of the meshing grid, so that no border point is inside.
inline constexpr int kImplicitPaddingCells = 2;  // [1]
// Levels of nested operations a scene may write; each level is one more call per grid point.
inline constexpr int kMaxCsgDepth = 16;  // [1]
// What loading one implicit shape may spend, in primitive evaluations: evaluating its tree on the
// meshing grid, on the body's grid, at the crossings and corners of its surface samples
// (geometry/feature_points.h) and their projections, each phi call costing the tree's primitive
// count and each gradient six calls; and checking and indexing its mesh, each triangle costing
// kImplicitEvaluationsPerTriangle. A primitive evaluation (with its share of the operations) took
// 24 to 27 ns in trees of 4096 tori, spheres or boxes and 38 ns in one of 4096 ellipsoids, the
// slowest (bench/csg_stress.py, one thread, the machine of bench/results/machine.csv): the budget
// is ~8 s of loading, ~10 s with the rest of the scene's work.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
// libFuzzer's build (tests/fuzz/run_fuzz.sh: -O1, AddressSanitizer, coverage on every comparison)
// runs these loops 12 to 15 times slower: the demo mug loads in 0.85 s here and over 10 s there.
// A budget 20 times smaller keeps the fuzzer's 10 s timeout for hangs, not for shapes within it.
inline constexpr double kMaxImplicitEvaluations = 1e7;  // [primitive evaluations]
#else
inline constexpr double kMaxImplicitEvaluations = 2e8;  // [primitive evaluations]
#endif
// The slowest measured cost, rounded up, to say the budget in seconds.
inline constexpr double kImplicitSecondsPerEvaluation = 4e-8;  // [s / primitive evaluation]
// A triangle of the mesh costs its closure and self-crossing checks, mass properties, search tree
// and surface samples: 9 to 12 us measured (400,000 to 1.7 million triangles), ~300 evaluations.
inline constexpr double kImplicitEvaluationsPerTriangle = 300.0;  // [primitive evaluations / triangle]

// The evaluations a shape's loading has spent: each stage charges before it evaluates (a grid)
// or as it goes (crossings, corners, projections), and the first charge past
// kMaxImplicitEvaluations throws ImplicitBudgetExceeded naming the stage, so no tree loads for
// longer than the budget allows, whatever its surface looks like.
class ImplicitBudgetExceeded : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};
class ImplicitBudget {
 public:
  explicit ImplicitBudget(int primitives, double limit = kMaxImplicitEvaluations)
      : primitives_(primitives), limit_(limit) {}
  // `calls` evaluations of the whole tree for `stage` ("the meshing grid", ...).
  void charge(double calls, const char* stage) { spend(calls * primitives_, stage); }
  // The checks a mesh of `triangles` goes through, charged when it is made, before they run.
  void chargeMesh(std::size_t triangles) {
    spend(double(triangles) * kImplicitEvaluationsPerTriangle, "the checks of its mesh", triangles);
  }
  double spent() const { return spent_; }  // [primitive evaluations]

 private:
  // A plain string, not std::string: charge runs at every evaluation of the samples' stage.
  void spend(double evaluations, const char* stage, std::size_t triangles = 0);

  double primitives_;
  double limit_;  // [primitive evaluations]
  double spent_ = 0.0;
};

struct ImplicitShape {
  std::shared_ptr<const ImplicitFunction> function;
  int resolution = kDefaultImplicitResolution;  // cells along the longest side [1], 4 to 1024
  // What its loading has spent; shared by the stages that build one body (scene/body_parser.cpp).
  // Null: unbudgeted (tests and tools that measure the cost itself).
  std::shared_ptr<ImplicitBudget> budget;
};

// The meshing grid: the function's bounds padded by kImplicitPaddingCells, cells of longest
// side / resolution.
GridLattice implicitGridLattice(const ImplicitShape& shape);
// Why sampling the shape would exceed kMaxSdfGridPoints, or its two grids alone
// kMaxImplicitEvaluations, e.g. "resolution 1024 lays a 1029 x 517 x 1029 grid (5.5e+08 points,
// ~22 GB); the limit is ...", or empty when both hold.
std::string implicitBudgetProblem(const ImplicitShape& shape);

struct ImplicitMeshing {
  Mesh mesh;                  // in the file frame, outward wound
  MarchingStats stats;
  GridLattice grid;             // the meshing grid
  double sampleSeconds = 0.0; // processor time of evaluating the function on the grid [s]
  double meshSeconds = 0.0;   // processor time of marching tetrahedra [s]
};

// Samples and meshes the shape. Throws std::invalid_argument when the resolution is out of range,
// over budget, the mesh would pass a mesh file's limits (kMaxMeshTriangles, kMaxMeshVertices),
// or no grid point is inside (an empty solid: a difference that removes everything,
// an intersection of disjoint operands, or a solid thinner than a cell).
ImplicitMeshing meshImplicitShape(const ImplicitShape& shape);

// The body's grid: phi at the points of sdfGridLattice(bodyMesh, {resolution}) laid over the
// body-frame mesh, evaluated at the file-frame point axes p + centre (MassModel's frame).
SignedDistanceGrid implicitBodyGrid(const ImplicitShape& shape, const Mesh& bodyMesh, const Mat3& axes,
                                    const Vec3& centre);

// An implicit body's exact solid in its body frame: phi(p) = f(axes p + centre), f the shape's
// function in the file frame (axes a rotation, so phi keeps f's distances).
struct ImplicitSolid {
  std::shared_ptr<const ImplicitFunction> function;
  Mat3 axes = Mat3::Identity();
  Vec3 centre = Vec3::Zero();   // [m]
  double gradientStep = 1e-6;   // central differences' step [m]

  double phi(const Vec3& p) const { return function->phi(axes * p + centre); }
  // Central differences of phi along the body axes: exact to O(step^2) where phi is smooth, the
  // mean of the faces' normals on an edge or at a corner.
  Vec3 gradient(const Vec3& p) const;
  // The point of the surface furthest along unit d near `start` (a surface point): where the
  // normal turns to d on a smooth patch, reached by Newton steps that model the patch as a sphere
  // of the radius its normals' turning shows; `start` itself at a corner or on a flat face, or
  // when no step gets further along d. Samples are a cell apart: a ball dropped on the ground
  // touches at its lowest sample, up to half a cell off centre, and would spin from the impulse.
  Vec3 supportNear(const Vec3& start, const Vec3& d, double cellSize) const;
};
// Steps of supportNear at most; each halves the angle between normal and d at least.
inline constexpr int kSupportSteps = 8;
// supportNear keeps a point only this close to the surface, as a fraction of a cell.
inline constexpr double kSupportOnSurface = 1e-9;  // [1]
// supportNear stops when the normal is within this angle of d.
inline constexpr double kSupportAngle = 1e-10;  // [rad]
// Central differences' step as a fraction of the solid's largest extent: far above rounding
// (1e-16 / 1e-6 of the extent in the difference) and far below any feature a grid can hold.
inline constexpr double kImplicitGradientRelStep = 1e-6;  // [1]
ImplicitSolid implicitSolidOf(const ImplicitShape& shape, const Mat3& axes, const Vec3& centre);

// The body's surface samples: one point on the exact surface per cell of its grid the surface
// crosses, sharp at edges and corners (geometry/feature_points.h).
// Charges `budget` (when not null) for every evaluation.
std::vector<Vec3> implicitSurfaceSamples(const ImplicitSolid& solid, const SignedDistanceGrid& bodyGrid,
                                         ImplicitBudget* budget = nullptr);
// The exact field of `solid` for geometry/feature_points.h, charging `budget` when not null.
ExactField implicitField(const ImplicitSolid& solid, ImplicitBudget* budget);

}  // namespace rbsim
