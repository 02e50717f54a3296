#pragma once
// Tetrahedral meshes for FEM soft bodies (seed 002 1.2): rest positions of the nodes and the
// tetrahedra as four node indices, positively oriented (det[X1-X0, X2-X0, X3-X0] > 0). Generated
// from a box; the boundary triangles are derived for drawing and for collisions.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

using Tet = std::array<std::uint32_t, 4>;

struct TetMesh {
  std::vector<Vec3> nodes;  // rest (material) positions [m]
  std::vector<Tet> tets;
  // Faces that belong to one tetrahedron only, wound counter-clockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> boundary;
};

// A box of full extents [m] centred on the origin, divided into nx * ny * nz cubes of six
// tetrahedra each (the Freudenthal-Kuhn split along the main diagonal, so neighbouring cubes'
// faces match and the mesh is conforming). Throws std::invalid_argument on non-positive input.
TetMesh makeTetBox(const Vec3& extents, int nx, int ny, int nz);

// The boundary faces of a tetrahedral mesh, outward wound.
std::vector<std::array<std::uint32_t, 3>> boundaryFaces(const std::vector<Vec3>& nodes, const std::vector<Tet>& tets);

// Empty when usable: indices in range, every tetrahedron of positive volume.
std::string checkTetMesh(const TetMesh& mesh);

}  // namespace rbsim
