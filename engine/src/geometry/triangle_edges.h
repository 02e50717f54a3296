#pragma once
// Which edges of a triangle mesh are real edges of its surface and which only join two triangles
// of one smooth or hollow stretch (Jolt's "active edges", MeshShape / ActiveEdges.h; Bullet's
// btInternalEdgeUtility keeps the same per-edge angle). A body sliding over a mesh must only
// feel the first kind: a contact normal taken from a flat or concave edge, or from a vertex
// between such edges, is an artefact of cutting the surface into triangles (the "internal edge"
// or "ghost collision" problem of Box2D's chain shapes).
#include <cstdint>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Two triangles sharing an edge whose normals are closer than this cosine (5 degrees apart, Jolt's
// default mActiveEdgeCosThresholdAngle) meet at a flat edge: it is never felt [1].
inline constexpr double kFlatEdgeCosine = 0.996194698;

// Bits 0, 1 and 2 set: all three edges of a triangle felt.
inline constexpr std::uint8_t kAllEdgesActive = 0x7;

// Per triangle, bit k set when its edge k (from vertex k to vertex k + 1 mod 3) is active: a
// boundary edge, an edge shared by more than two triangles, or a convex edge sharper than
// kFlatEdgeCosine. Flat and concave edges are inactive. Edges are matched by vertex index.
std::vector<std::uint8_t> activeEdges(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);

}  // namespace rbsim
