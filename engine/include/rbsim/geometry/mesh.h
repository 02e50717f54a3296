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

// The tolerance a mesh's convexity is judged with (isConvexSurface), from its coordinates as
// written, before any re-centring: the larger of a fraction of its size and the rounding of
// coordinates stored in single precision (issue 34). A dent shallower than this is rounding or a
// hull builder's merged faces, and the body collides as its convex hull; a deeper one gets a grid.
//
// Float rounding: a coordinate stored as a float is off by up to |p_i| 2^-24, and a plane through
// three such vertices inherits a few times that. Gregorius ("Implementing QuickHull", GDC 2014)
// bounds the error of a plane distance from float vertices by 3 (sum_i max |p_i|) FLT_EPSILON (the
// coplanarity distance of Box3D's hull.c, b3HullBuilder_ComputeTolerance, and of Jolt's
// ConvexHullBuilder::DetermineCoplanarDistance), and Box3D's builder adds a point to a hull only
// when it lies more than 8 such distances outside (minOutside = 2 minRadius = 8 tolerance): a hull
// built in float may leave its own input that far outside its faces.
inline constexpr double kConvexFloatTolerance = 24.0;  // [1]: x FLT_EPSILON x sum_i max |p_i| [m]
// Size: such a builder also merges nearly coplanar faces into one polygon, and a triangulation of
// that polygon puts a vertex off a triangle's plane by a multiple of the merge distance that the
// triangles' shapes set: Box3D's convex pile hull (32 points on a sphere of radius 2, 6.44 m
// across) with one nearly planar quad split along its other diagonal has a vertex 7.7e-5 m, 1.2e-5
// of its size, outside a face. 1e-4 of the size keeps 8 times that, and stays below a 1 mm notch
// in a 1 m body (5.8e-4 of its 1.73 m diagonal) and 1/30 of the 5 mm contact slop on such a body.
inline constexpr double kConvexRelativeTolerance = 1e-4;  // [1] of the bounding box's diagonal
// max(kConvexRelativeTolerance x diagonal, kConvexFloatTolerance x FLT_EPSILON x sum_i max |p_i|)
// [m], over `mesh`'s vertices; 0 for a mesh without vertices.
double convexityTolerance(const Mesh& mesh);

// Moves every vertex by -offset (used to re-centre a mesh on its centre of mass).
void translateMesh(Mesh& mesh, const Vec3& offset);

}  // namespace rbsim
