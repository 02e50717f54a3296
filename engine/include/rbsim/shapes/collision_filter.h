#pragma once
// Which shapes may touch (Box2D v3's b2Filter and b2ShouldShapesCollide, src/shape.c): each
// shape is in some categories and accepts some; a group index overrides both for shapes that
// share it. Checked per pair of shapes before the narrow phase, so a filtered pair costs nothing.
#include <cstdint>

namespace rbsim {

struct CollisionFilter {
  std::uint64_t category = 1;         // the categories this shape is in, one bit each
  std::uint64_t mask = ~std::uint64_t{0};  // the categories it collides with
  // Shapes with the same non-zero group always collide (> 0) or never (< 0), whatever their
  // categories and masks (a ragdoll's limbs: one negative group per ragdoll). 0: no group.
  std::int32_t group = 0;

  friend bool operator==(const CollisionFilter& a, const CollisionFilter& b) {
    return a.category == b.category && a.mask == b.mask && a.group == b.group;
  }
};

// Box2D v3's rule: a shared non-zero group decides alone; otherwise each mask must accept the
// other's category.
inline bool shouldCollide(const CollisionFilter& a, const CollisionFilter& b) {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.mask & b.category) != 0 && (a.category & b.mask) != 0;
}

// True for the default filter, which collides with every other default one: the pipeline skips
// the check for pairs of such shapes.
inline bool isDefaultFilter(const CollisionFilter& f) { return f == CollisionFilter{}; }

}  // namespace rbsim
