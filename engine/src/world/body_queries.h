#pragma once
// The exact answer of one body or one plane to each scene query (world/world_queries.h): what the
// tree walks call at its leaves, and what the tests' brute force calls for every body. They fill
// QueryHit's distance, point, normal and child; the caller names the body or plane.
#include <optional>

#include "rbsim/body/rigid_body.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/shapes/plane.h"
#include "rbsim/world/world_queries.h"

namespace rbsim {

// Box2D v3's b2ShouldQueryShape (src/shape.c): the shape is in a category the query sees, and
// its mask accepts the query's category.
inline bool passes(const CollisionFilter& shape, const QueryFilter& query) {
  return (shape.category & query.mask) != 0 && (shape.mask & query.category) != 0;
}
// Whether the filter lets any of the body's shapes through (its own, or a compound's children's).
bool anyShapePasses(const RigidBody& body, const QueryFilter& filter);
// Planes count as default shapes.
inline bool planePasses(const QueryFilter& filter) { return filter.planes && passes(CollisionFilter{}, filter); }

// The ray origin + s d, 0 <= s <= reach, |d| = 1, against the body: its nearest hit.
std::optional<QueryHit> rayBody(const RigidBody& body, const Vec3& origin, const Vec3& d, double reach,
                                const QueryFilter& filter);
std::optional<QueryHit> rayPlane(const Plane& plane, const Vec3& origin, const Vec3& d, double reach);

// The body's surface point nearest p, with the signed distance (< 0 inside; a mesh body's, its
// triangles', is >= 0).
std::optional<QueryHit> closestOnBody(const RigidBody& body, const Vec3& p, const QueryFilter& filter);
QueryHit closestOnPlane(const Plane& plane, const Vec3& p);

// Whether `shape` (a sphere, box or capsule as a Shape, at pose R, x) touches the body or plane.
std::optional<QueryHit> overlapBody(const RigidBody& body, const Shape& shape, const Mat3& R, const Vec3& x,
                                    const QueryFilter& filter);
bool overlapsPlane(const Plane& plane, const Shape& shape, const Mat3& R, const Vec3& x);

// `shape` at pose R, x moved along d (|d| = 1) by up to reach: its first contact with the body or plane.
std::optional<QueryHit> castBody(const RigidBody& body, const Shape& shape, const Mat3& R, const Vec3& x,
                                 const Vec3& d, double reach, const QueryFilter& filter);
std::optional<QueryHit> castPlane(const Plane& plane, const Shape& shape, const Mat3& R, const Vec3& x,
                                  const Vec3& d, double reach);

}  // namespace rbsim
