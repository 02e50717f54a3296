#pragma once
// A World's shapes by id (world/item_ids.h ShapeId; Box2D v3's b2ShapeId, b2Shape_IsValid,
// b2Shape_GetBody, b2Body_GetShapes): free functions over World (docs/architecture.md, "The
// World's surface"; engine/src/world/shape_ids.cpp). A shape is a compound body's child
// (RigidBody::children()) or a body of one shape's shape (child 0). Every body added gets its
// shapes' ids in child order; destroying the body (destroyBody, destroyBodies, the kill volume) or
// breaking it (fracture: the body keeps its id, its pieces' shapes get new ones) makes them stale.
// Ray casts, queries (world/world_queries.h QueryHit::shape, world/ray_cast.h) and contact events
// (world/contact_events.h ContactPair::shapeA, shapeB) name the shapes they report.
#include <cstddef>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/world/item_ids.h"

namespace rbsim {

class World;

// False for a stale id: its body destroyed or broken, or never made here.
bool isValid(const World& world, ShapeId shape);
// The shape's body, and its index in the body's children (0 for a body of one shape); each throws
// std::invalid_argument naming the call for a stale id.
BodyId bodyOf(const World& world, ShapeId shape);
std::size_t childOf(const World& world, ShapeId shape);
// The id of the body's child `child` (0 for a body of one shape), and of all its shapes in child
// order; throw std::invalid_argument naming the call for a stale body id or a child out of range.
ShapeId shapeIdAt(const World& world, BodyId body, std::size_t child);
std::vector<ShapeId> shapeIds(const World& world, BodyId body);

}  // namespace rbsim
