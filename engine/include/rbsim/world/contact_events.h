#pragma once
// Contact events of the last step, read after World::step (Box3D's b3ContactEvents, Box2D v3's
// b2ContactEvents: physics_world.c b3UpdateContacts, solver.c's hit events): the pairs of shapes
// that began or stopped touching, and those that hit each other faster than
// Settings::hitEventSpeed. A pair is named as the contact names it (collision/contact.h): A then
// B, the normal from A towards B; a plane is side A, with `plane` its index and `bodyA` no body
// (BodyId{}, slot UINT32_MAX). A compound's shapes are its children (body/child_shape.h); a
// body of one shape and a plane are child 0.
#include <cstdint>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"
#include "rbsim/world/item_ids.h"

namespace rbsim {

class World;

inline constexpr std::int64_t kNoPlane = -1;  // ContactPair::plane between two bodies

struct ContactPair {
  BodyId bodyA, bodyB;  // bodyA is BodyId{} when A is a plane
  std::int64_t plane = kNoPlane;  // the plane A's index in World::planes(), or kNoPlane
  std::uint16_t childA = 0, childB = 0;
  // The two shapes' ids (world/shape_ids.h) when the event was made: a plane's side is ShapeId{}.
  // An end event of a destroyed or broken body names the ids it had, now stale.
  ShapeId shapeA, shapeB;
};

// The pair's manifold first has points: the shapes touch, or are within the contact margin of
// touching (a speculative contact, as Box3D's begin events are).
struct ContactBeginEvent {
  ContactPair pair;
  Vec3 point = Vec3::Zero();   // the manifold's deepest point, midway between the surfaces [m]
  Vec3 normal = Vec3::UnitY();  // unit, from A towards B
  double depth = 0.0;           // at that point [m]; < 0 apart (speculative)
};

// The pair's manifold has no points any more, or one of its bodies was destroyed, removed by the
// kill volume or broken by fracture (then its id is stale). It names the pair as its begin did.
struct ContactEndEvent {
  ContactPair pair;
};

// A point of the pair's manifold took a normal impulse this step while the two approached along
// the normal faster than Settings::hitEventSpeed (Box3D's b3ContactHitEvent): the fastest such
// point of the manifold. At most one a touching: the first step that pushes this fast after the
// begin (a landing the soft step brakes over two steps is one hit); the pair must end and begin
// again to be hit again.
struct ContactHitEvent {
  ContactPair pair;
  Vec3 point = Vec3::Zero();    // world [m], midway between the surfaces
  Vec3 normal = Vec3::UnitY();  // unit, from A towards B
  double approachSpeed = 0.0;   // -u_rel,N before the step's solve [m/s], > hitEventSpeed
};

struct ContactEvents {
  std::vector<ContactBeginEvent> begin;
  std::vector<ContactEndEvent> end;
  std::vector<ContactHitEvent> hit;
  void clear() {
    begin.clear();
    end.clear();
    hit.clear();
  }
};

// The World's events of its last step (a free function over World: docs/architecture.md, "The World's surface").
// The ends of pairs whose body destroyBody removed between steps come with the next step's. A
// step that throws leaves the last successful step's events in place.
const ContactEvents& contactEvents(const World& world);

}  // namespace rbsim
