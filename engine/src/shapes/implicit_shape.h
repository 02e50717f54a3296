#pragma once
// A body whose solid is an analytic implicit function or a CSG tree of them (geometry/csg.h).
// The exact function is sampled on a grid twice: over its bounds in the file frame, where marching
// tetrahedra mesh it for drawing and mass properties (geometry/marching_tetrahedra.h), and over
// the mesh in the body frame, where the samples are the body's signed distance grid (seed 000
// "Discrete Implicit Surfaces": "store values of the function at grid points") for the narrow
// phase, exactly as a mesh body's grid (collision/narrowphase/sdf_contact.h).
#include <memory>
#include <string>

#include "geometry/csg.h"
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
// Budget of evaluating the tree on one grid: grid points x primitives, ~10 s at ~10 ns each.
inline constexpr double kMaxImplicitEvaluations = 1e9;  // [primitive evaluations]

struct ImplicitShape {
  std::shared_ptr<const ImplicitFunction> function;
  int resolution = kDefaultImplicitResolution;  // cells along the longest side [1], 4 to 1024
};

// The meshing grid: the function's bounds padded by kImplicitPaddingCells, cells of longest
// side / resolution.
GridLattice implicitGridLattice(const ImplicitShape& shape);
// Why sampling the shape would exceed kMaxSdfGridPoints or kMaxImplicitEvaluations, e.g.
// "resolution 1024 lays a 1029 x 517 x 1029 grid (5.5e+08 points, ~22 GB); the limit is ...", or
// empty when both hold.
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

}  // namespace rbsim
