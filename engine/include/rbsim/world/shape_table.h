#pragma once
// The ids of a World's shapes (world/item_ids.h ShapeId), as Box2D v3 keeps its shapes (src/shape.c
// b2CreateShapeInternal, b2DestroyShapeInternal: an id pool over the shape array, each body the
// head of a list of its shapes): per slot its generation, the id slot of its body (BodyId::slot,
// which a body keeps when its index moves) and its child, and the link to the body's next shape,
// or for a free slot the next free slot. Per body id slot, its first shape. A body's shapes are
// made in child order when it is added and retired together, so adding and removing cost what the
// body has, never what the World has (a pass over every shape would make a removal cost the World).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/world/item_ids.h"

namespace rbsim {

// A compound body's shapes are its children; any other body has one.
inline std::size_t shapeCountOf(const RigidBody& body) { return body.isCompound() ? body.children().size() : 1; }

class ShapeTable {
 public:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  struct Slot {
    std::uint32_t generation = 0;
    std::uint32_t body = kNone;  // its body's id slot; kNone: a free slot
    std::uint32_t child = 0;     // its index in the body's children (0 for a body of one shape)
    std::uint32_t next = kNone;  // the body's next child's slot, or, free, the next free slot
  };

  // Gives the body in id slot `bodySlot` (which has none) `count` shapes, children 0, 1, ... in order.
  void add(std::uint32_t bodySlot, std::size_t count);
  // Retires that body's shapes, child 0 first: each slot's generation moves on and it joins the
  // free list, so a kept id is stale even once its slot names a new shape.
  void retire(std::uint32_t bodySlot);
  bool isValid(ShapeId id) const {
    return id.slot < slots_.size() && slots_[id.slot].body != kNone && slots_[id.slot].generation == id.generation;
  }
  const Slot& slot(ShapeId id) const { return slots_[id.slot]; }  // of a valid id
  // The id of child `child` of the body in id slot `bodySlot` (a living body, child in range).
  ShapeId idOf(std::uint32_t bodySlot, std::size_t child) const;

  // For a snapshot (world/world_snapshot.cpp): the slots and the free list's head as they are, and
  // set back from them after checking them against the bodies (shapeCounts[s]: the number of
  // shapes of the body in id slot s, 0 for a free one): each body's shapes are its children in
  // order, linked in that order, and the free list runs through the other slots exactly once.
  // Returns what is wrong ("" when nothing is; the table is then set).
  const std::vector<Slot>& slots() const { return slots_; }
  std::uint32_t freeSlot() const { return freeSlot_; }
  std::string assign(std::vector<Slot> slots, std::uint32_t freeSlot, const std::vector<std::size_t>& shapeCounts);

 private:
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> firstOfBody_;  // per body id slot: child 0's shape slot, kNone when no body
  std::uint32_t freeSlot_ = kNone;          // head of the free list
};

}  // namespace rbsim
