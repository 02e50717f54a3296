#pragma once
// The zero set of sampled implicit values as a triangle mesh, by marching tetrahedra (Doi and
// Koide 1991, "An efficient method of triangulating equi-valued surfaces by using tetrahedral
// cells", IEICE Transactions E74(1); the tetrahedral form of Lorensen and Cline's 1987 marching
// cubes). Each cell is cut into the six tetrahedra around its main diagonal (Kuhn's subdivision),
// which every neighbouring cell cuts the same way on their shared face, so the surface has no
// holes and, unlike marching cubes, no ambiguous case. In a tetrahedron the values are linear:
// the surface is one triangle or one quadrilateral (two triangles), with a vertex on every edge
// whose ends differ in sign, at the zero of the linear interpolation. A vertex is shared by all
// cells around its edge, and every triangle faces from phi < 0 to phi >= 0, so the mesh is closed
// and consistently wound (outward normals) when no point on the grid's border is inside.
#include <cstddef>
#include <vector>

#include "rbsim/geometry/grid_lattice.h"
#include "rbsim/geometry/mesh.h"

namespace rbsim {

// A value within this fraction of a cell of zero is taken as exactly zero (outside): the surface
// then runs through that grid point, and every edge from it to an inside point puts its vertex
// there, shared. A value of rounding size left as it is would put a vertex mid-way between two
// such points as well as on them: three in a line, a zero-area triangle. Moves the surface by at
// most 1e-6 of a cell.
inline constexpr double kMarchingZeroBand = 1e-6;  // [1]
// Any other crossing is placed at least this fraction of its edge from either end. A value just
// past the zero band put vertices that close to the grid point on every edge around it, slivers
// thin enough for rounding to make them cross (issue 37: a plain torus, R = 0.5, r = 0.15, was
// refused as self-crossing at 11 of the 91 resolutions from 40 to 130). Kept on its own edge the
// vertex leaves the topology as it was (a wider zero band would not: more points on the surface,
// more sheets meeting at one), and moves the surface by at most 1e-3 of a cell, far below the
// interpolation's own error.
inline constexpr double kMarchingVertexMargin = 1e-3;  // [1]

struct MarchingStats {
  std::size_t insidePoints = 0;      // grid points with phi < 0 (beyond the zero band)
  std::size_t snappedVertices = 0;   // vertices on grid points of value zero
  std::size_t droppedTriangles = 0;  // collapsed: two corners on one such grid point
};

// `values` holds phi at the points of `grid` (GridLattice::index order). Throws std::invalid_argument
// when their counts differ or a value is not finite. The mesh is empty when no point is inside.
Mesh marchingTetrahedra(const GridLattice& grid, const std::vector<double>& values, MarchingStats* stats = nullptr);

}  // namespace rbsim
