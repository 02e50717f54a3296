#pragma once
// The narrow phase of a static triangle-mesh ground (a terrain or a level read from an OBJ): a
// static body of ShapeType::Mesh with a triangle hierarchy (BodyDef::triangles) and no signed
// distance grid. Every shape of a body near it (its one shape, or each child of a compound)
// asks the hierarchy for the triangles its box meets, inflated by the margin, and collides with
// each on its own (collision/narrowphase/shape_triangle.h), as Jolt's MeshShape and Bullet's
// btBvhTriangleMeshShape do: one Contact per touched triangle.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/contact.h"

namespace rbsim {

// A contact's part (the solver's warm-start key, below 2^15) for triangle t and child c of the
// other body: (t + kMeshGroundChildStride c) mod 2^15. Stable while the same triangle is touched,
// distinct for every touched triangle of a shape unless two are 2^15 apart in the mesh; two
// children share one only when their triangles' indices differ by a multiple of the stride. A
// shared key costs a worse first guess of the impulse, never a wrong contact.
inline constexpr std::uint32_t kMeshGroundChildStride = 4099;  // [triangles], prime
std::uint16_t meshGroundPart(std::uint32_t triangle, std::size_t child);

// Whether the body collides as a mesh ground: static, a mesh with triangles and without a grid.
bool isMeshGround(const RigidBody& body, const BodySolid& solid);

// Contacts of mesh ground `ground` (index ig, triangles in its body frame) and body `other`
// (index io), appended to `out`: a is the ground when `groundFirst` (the pair's order,
// CollisionPipeline::bodiesOf), the normal from a to b. `margin` [m]: the contact margin with
// both bodies' reach.
void collideMeshGround(const RigidBody& ground, std::size_t ig, const TriangleBvh& triangles, const RigidBody& other,
                       std::size_t io, bool groundFirst, double margin, std::vector<Contact>& out);

}  // namespace rbsim
