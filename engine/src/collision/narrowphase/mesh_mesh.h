#pragma once
// Contact between two non-convex triangle meshes from where their surfaces cross (seed 004
// "Triangle intersection"). The meshes' bounding-volume hierarchies descend together to the
// triangle pairs whose boxes overlap (TriangleBvh::overlappingPairs), Moller's test
// (triangle_triangle.h) gives each crossing pair's intersection segment, and the segment's
// midpoint is a contact point. Its normal and depth are the pair's axis of least penetration among
// the separating axis test's candidates (the face normals and the edge-edge cross products): a
// box sunk into a box is pushed out along the face normal even where two side walls cross in the
// sunk band. The points are grouped by normal into manifolds (sdf_contact.h).
//
// Only surfaces that cross make contact: a mesh wholly inside the other, or one apart by any gap,
// gives none (the signed distance path of sdf_contact.h answers both, to its grid's accuracy).
#include <cstdint>
#include <utility>
#include <vector>

#include "rbsim/collision/contact.h"
#include "rbsim/geometry/mesh.h"
#include "geometry/triangle_bvh.h"
#include "rbsim/math/types.h"

namespace rbsim {

// A mesh where its body is, with the hierarchy built over the same body-frame triangles.
struct PosedMesh {
  const Mesh* mesh = nullptr;
  const TriangleBvh* bvh = nullptr;
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();  // [m]
};

// The pairs (triangle of A, triangle of B) whose surfaces cross by Moller's test, found through
// the hierarchies; sorted.
std::vector<std::pair<std::uint32_t, std::uint32_t>> crossingTriangles(const PosedMesh& a, const PosedMesh& b);

// The manifolds of the pair, normal from A to B.
std::vector<ContactManifold> collideMeshes(const PosedMesh& a, const PosedMesh& b);

}  // namespace rbsim
