#pragma once
// Handles to a World's joints, springs and shapes that outlive index changes, as BodyId does for bodies
// (body/body_id.h; Box2D v3's b2JointId): the slot they name and the slot's generation when they
// were made. Removing the joint or spring (by hand, or with one of its bodies) moves the slot's
// generation on, so a kept handle is recognised as stale, even once the slot holds a new one.
#include <cstdint>

namespace rbsim {

struct JointId {
  std::uint32_t slot = UINT32_MAX;  // UINT32_MAX: no joint
  std::uint32_t generation = 0;
  friend bool operator==(const JointId& a, const JointId& b) { return a.slot == b.slot && a.generation == b.generation; }
  friend bool operator!=(const JointId& a, const JointId& b) { return !(a == b); }
};

// A body's shape: one child of a compound body (RigidBody::children()), or the one shape of a
// body of one shape (Box2D v3's b2ShapeId). Made when its body is added; destroying the body (by
// hand, by the kill volume, or by fracture, which gives the broken body its first piece's shapes)
// moves the slot's generation on. Read through world/shape_ids.h.
struct ShapeId {
  std::uint32_t slot = UINT32_MAX;  // UINT32_MAX: no shape (a plane's side of a contact)
  std::uint32_t generation = 0;
  friend bool operator==(const ShapeId& a, const ShapeId& b) { return a.slot == b.slot && a.generation == b.generation; }
  friend bool operator!=(const ShapeId& a, const ShapeId& b) { return !(a == b); }
};

struct SpringId {
  std::uint32_t slot = UINT32_MAX;  // UINT32_MAX: no spring
  std::uint32_t generation = 0;
  friend bool operator==(const SpringId& a, const SpringId& b) { return a.slot == b.slot && a.generation == b.generation; }
  friend bool operator!=(const SpringId& a, const SpringId& b) { return !(a == b); }
};

}  // namespace rbsim
