#pragma once
// Scene queries through a bounding volume hierarchy over the bodies' boxes (issue 57; Box2D v3's
// b2World_CastRay / b2World_CastShape / b2World_OverlapShape / b2World_OverlapAABB, PyBullet's
// rayTestBatch, MuJoCo's mj_ray): rays, one or a batch, swept spheres, boxes and capsules, the
// bodies a shape overlaps, the nearest surface point and the bodies whose box meets a box. The
// hierarchy (world/query_tree.h) is built on the first query after the World changed (a step, a
// body added or destroyed, World::body handed out for a change) and shared by the queries after
// it: a batch of queries between steps pays for one build. Every body answers, asleep and static
// ones too, and the World's planes; a compound body by its children, each with its own filter;
// a ShapeType::Mesh body by its triangles (its surface, as it is drawn).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/math/types.h"
#include "rbsim/world/item_ids.h"

namespace rbsim {

class World;

// Which shapes a query sees (Box2D v3's b2QueryFilter and b2ShouldQueryShape, src/shape.c): a
// shape whose CollisionFilter (shapes/collision_filter.h) is in a category of `mask` and whose
// own mask accepts `category`. Groups play no part. Planes count as default filters (category 1,
// every mask bit), and `planes` false leaves them out.
struct QueryFilter {
  std::uint64_t category = 1;               // the categories the query is in, one bit each
  std::uint64_t mask = ~std::uint64_t{0};   // the categories it sees
  bool planes = true;
};

// What a query found: a body (and which child of a compound, and that shape's id) or a plane.
struct QueryHit {
  bool isPlane = false;
  BodyId body;               // when !isPlane
  int child = -1;            // the compound child hit, an index into RigidBody::children(); -1 for a body of one shape
  ShapeId shape;             // the shape hit (world/shape_ids.h): that child, or the body's one shape; ShapeId{} for a plane
  std::size_t plane = 0;     // when isPlane: an index into World::planes()
  double distance = 0.0;     // [m] along the unit direction (casts) or to the surface (closest point)
  Vec3 point = Vec3::Zero();     // on the surface of what was hit, world frame [m]
  Vec3 normal = Vec3::UnitY();   // its outward unit normal there, world frame
};

// The nearest hit of origin + s d, 0 <= s <= maxDistance, d = direction / |direction| (as
// rayCast in world/ray_cast.h, which answers the same through this). Throws std::invalid_argument
// for a zero or non-finite direction, a non-finite origin or a negative or NaN maxDistance.
std::optional<QueryHit> castRay(const World& world, const Vec3& origin, const Vec3& direction, double maxDistance,
                                const QueryFilter& filter = {});
// One ray per row: the same as castRay on each, with one check of the tree for all. Throws as
// castRay does, naming the row, before casting any; or when the sizes differ.
std::vector<std::optional<QueryHit>> castRays(const World& world, const std::vector<Vec3>& origins,
                                              const std::vector<Vec3>& directions, double maxDistance,
                                              const QueryFilter& filter = {});

// A convex shape to sweep or overlap, centred at `position` and turned by `orientation`: a sphere
// (radius), a box (halfExtents) or a capsule (radius, halfLength along its local y).
struct QueryShape {
  enum class Kind { Sphere, Box, Capsule };
  Kind kind = Kind::Sphere;
  double radius = 0.0;                  // sphere, capsule [m]
  double halfLength = 0.0;              // capsule [m]
  Vec3 halfExtents = Vec3::Zero();      // box [m]
  Vec3 position = Vec3::Zero();         // [m]
  Quat orientation = Quat::Identity();  // unit
  static QueryShape sphere(double radius, const Vec3& position);
  static QueryShape box(const Vec3& halfExtents, const Vec3& position, const Quat& orientation = Quat::Identity());
  static QueryShape capsule(double radius, double halfLength, const Vec3& position,
                            const Quat& orientation = Quat::Identity());
};

// The first contact of `shape` translated along d = direction / |direction| by up to maxDistance:
// distance is how far it moved [m], point the contact point and normal the hit surface's outward
// normal there (towards the moving shape). Conservative advancement on the GJK distance of the
// cores (Mirtich 1996, "Impulse-based dynamic simulation", ch. 3; Box2D v3's b2ShapeCast,
// src/distance.c, answers the same question), to kShapeCastTolerance. A shape that already
// touches something hits it at 0 with the normal -d. Throws std::invalid_argument on a bad shape,
// direction or distance.
std::optional<QueryHit> castShape(const World& world, const QueryShape& shape, const Vec3& direction,
                                  double maxDistance, const QueryFilter& filter = {});
// How near the swept shape stops to what it hits [m]; the reported distance is within this of the
// exact time of impact, never past it.
inline constexpr double kShapeCastTolerance = 1e-6;

// Every body (once, with the first child found) and plane that `shape` overlaps or touches.
// Sorted: bodies by their index in World::bodies(), then planes.
std::vector<QueryHit> overlapShape(const World& world, const QueryShape& shape, const QueryFilter& filter = {});

// The surface point nearest `point` within maxDistance (infinity: anywhere): the body or plane,
// the point, the outward normal there and the signed distance (< 0 inside a solid; the deepest
// one wins). Empty when nothing is that near.
std::optional<QueryHit> closestPoint(const World& world, const Vec3& point, double maxDistance,
                                     const QueryFilter& filter = {});

// The bodies whose box (the broad phase's, before its contact margin: the shape's exact world
// bounds, its children's for a compound) overlaps `box`, by index in World::bodies(). The filter
// is the body's own (a compound's children do not take part). Throws on a box with a NaN.
std::vector<BodyId> queryAabb(const World& world, const Aabb& box, const QueryFilter& filter = {});

}  // namespace rbsim
