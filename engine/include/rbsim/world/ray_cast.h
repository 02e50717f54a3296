#pragma once
// The first thing a ray meets in a World (issue 39; PyBullet's rayTest, MuJoCo's mj_ray): a body
// or a plane, with the point, the outward normal there and the distance. Spheres, capsules,
// boxes, rounded boxes and hulls answer exactly (collision/shape_queries.h, in the body's frame);
// a mesh body (ShapeType::Mesh) by its triangles facing the ray (Moller and Trumbore 1997), as it
// is drawn; a plane by its equation. Every body answers, asleep and static ones too, through the
// World's bounding volume hierarchy (world/world_queries.h's castRay, which also filters, names a
// compound's child and casts batches).
#include <cstddef>
#include <optional>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"
#include "rbsim/world/item_ids.h"

namespace rbsim {

class World;

struct WorldRayHit {
  bool isPlane = false;
  BodyId body;             // the body hit (when !isPlane)
  ShapeId shape;           // its shape hit (world/shape_ids.h; a compound's child); ShapeId{} for a plane
  std::size_t plane = 0;   // the plane hit, an index into World::planes() (when isPlane)
  double distance = 0.0;   // along the unit direction [m]
  Vec3 point = Vec3::Zero();     // where it hits, world frame [m]
  Vec3 normal = Vec3::UnitY();   // outward unit normal there, world frame
};

// The nearest hit of origin + s d, 0 <= s <= maxDistance, d = direction / |direction|; empty when
// nothing is hit. A ray starting inside a body hits it at distance 0. Throws std::invalid_argument
// for a zero or non-finite direction, a non-finite origin or a negative or NaN maxDistance.
std::optional<WorldRayHit> rayCast(const World& world, const Vec3& origin, const Vec3& direction, double maxDistance);

}  // namespace rbsim
