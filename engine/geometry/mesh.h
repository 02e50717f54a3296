#pragma once
// Vertex-list geometry (seed 004 "Rigid body geometry"): body-space vertices and triangles.
// The world-space copy p' = R p + x lives with the body (body/rigid_body.h).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

using Triangle = std::array<std::uint32_t, 3>;  // indices into Mesh::vertices, counter-clockwise
                                                // seen from outside (outward normal by right hand)

// Budget on a mesh read from a file (checked by the OBJ loader before it stores any): every pass
// over a body's mesh (closedness, convexity and self-crossing checks, mass integrals, the grid's
// exact band) is O(n log n) or better, and at this size they take a few seconds together.
inline constexpr std::size_t kMaxMeshVertices = 1000000;   // [vertices]
inline constexpr std::size_t kMaxMeshTriangles = 2000000;  // [triangles]: a closed mesh has ~2 per vertex

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

// Whether no vertex lies outside any triangle's plane by more than `tolerance` [m]. For a closed,
// consistently wound, non-degenerate mesh (checkMesh) in O(n) for a convex mesh, not the O(faces x
// vertices) of testing every pair: the centroid must lie behind every face plane and the surface
// wind once around it (so the surface is one sheet, star-shaped about the centroid), and from each
// face a walk over the vertex graph climbing the face's plane distance (a convex mesh's faces are
// already at the top) must not rise above the tolerance, which also catches dents too gentle for
// any single edge to show. Vertices no triangle uses, and every vertex of any other mesh, are
// tested against every plane, as is every vertex when the walks exceed kConvexityWorkPerTriangle.
// Answers false (not convex) when that plain test would exceed kMaxConvexityWork: that only costs
// a convex body a signed distance grid.
bool isConvexSurface(const Mesh& mesh, double tolerance);
// Plane distance evaluations isConvexSurface may spend: per triangle on the walks (a convex mesh
// needs ~3 x 6, its corners' neighbours), and in all on the brute-force test of the rest.
inline constexpr double kConvexityWorkPerTriangle = 64.0;  // [evaluations / triangle]
inline constexpr double kMaxConvexityWork = 1e8;           // [evaluations], ~0.1 s

// Moves every vertex by -offset (used to re-centre a mesh on its centre of mass).
void translateMesh(Mesh& mesh, const Vec3& offset);

}  // namespace rbsim
