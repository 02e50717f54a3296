#pragma once
// Vertex-list geometry (seed 004 "Rigid body geometry"): body-space vertices and triangles.
// The world-space copy p' = R p + x lives with the body (body/rigid_body.h).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "math/types.h"

namespace rbsim {

using Triangle = std::array<std::uint32_t, 3>;  // indices into Mesh::vertices, counter-clockwise
                                                // seen from outside (outward normal by right hand)

struct Mesh {
  std::string name;              // file path or primitive name, for messages
  std::vector<Vec3> vertices;    // body space [m]
  std::vector<Triangle> triangles;

  Vec3 boundsMin() const;
  Vec3 boundsMax() const;
};

// The axis-aligned box of the given full extents [m], centred on the origin: the seed's 8
// vertices p0..p7 (scaled) and 12 outward-facing triangles.
Mesh makeBox(const Vec3& extents);

// Topology facts needed before trusting a mesh for exact mass properties.
struct MeshCheck {
  bool closed = false;              // every edge shared by exactly two triangles
  bool consistentlyOriented = false;// each shared edge traversed once in each direction
  std::size_t degenerateTriangles = 0;  // zero-area triangles or repeated indices
  std::string problem;              // first problem found, in words; empty when none
};
MeshCheck checkMesh(const Mesh& mesh);

// Moves every vertex by -offset (used to re-centre a mesh on its centre of mass).
void translateMesh(Mesh& mesh, const Vec3& offset);

}  // namespace rbsim
