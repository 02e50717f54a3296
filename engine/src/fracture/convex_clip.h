#pragma once
// Cutting a closed convex mesh by a plane, the building block of fracture by planes and by
// Voronoi cells (seed 000 "Fracture": "the mass and inertia tensor of each new piece can be
// computed based on the geometry", so every piece must be a closed, outward-wound mesh that
// polyhedralMassProperties accepts).
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

// The part of a closed convex mesh on the side normal . p <= offset, closed by a cap on the plane
// (a fan around the centroid of the cut's boundary loop, outward normal +normal). Vertices within
// `tolerance` of the plane count as on it, so no sliver triangles appear. The mesh comes back
// unchanged when it lies wholly on the kept side, empty (no triangles) when wholly on the other.
// normal must be unit; tolerance [m] >= 0.
Mesh clipConvexMesh(const Mesh& convex, const Vec3& normal, double offset, double tolerance);

// A tolerance for clipConvexMesh scaled to a mesh: this fraction of its bounding-box diagonal.
inline constexpr double kClipRelativeTolerance = 1e-9;  // [1]
double clipTolerance(const Mesh& mesh);  // [m]

}  // namespace rbsim
