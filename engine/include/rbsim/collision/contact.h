#pragma once
// What the narrow phase reports for one touching pair: a manifold of up to four points sharing
// one normal (seed 004 "Collision detection": contact point, normal, penetration depth).
#include <array>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "rbsim/math/types.h"
#include "rbsim/shapes/plane.h"

namespace rbsim {

struct ContactPoint {
  Vec3 position = Vec3::Zero();  // world frame [m], midway between the two surfaces
  // Penetration depth [m] along the normal: > 0 when the surfaces overlap, <= 0 when they are
  // apart by -depth (speculative contacts, within the contact margin).
  double depth = 0.0;
  // Where body B's copy of the point lies from body A's [m]: zero for a manifold computed this
  // step; a recycled one (world/contact_recycling.h) keeps each body's lever arm as it was when
  // computed, A's copy at position - offset / 2 and B's at position + offset / 2.
  Vec3 offset = Vec3::Zero();
};
// 56 bytes: position, depth, offset. Four make a manifold's 224.
static_assert(sizeof(ContactPoint) == 56, "ContactPoint's size: see the comment above");

inline constexpr int kMaxManifoldPoints = 4;

struct ContactManifold {
  Vec3 normal = Vec3::UnitY();  // unit, world frame, pointing from A towards B
  std::array<ContactPoint, kMaxManifoldPoints> points{};
  int count = 0;  // 0 means no contact

  void add(const Vec3& position, double depth) {
    if (count < kMaxManifoldPoints) points[count++] = {position, depth, Vec3::Zero()};
  }
  double maxDepth() const {
    double d = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < count; ++i) d = std::max(d, points[i].depth);
    return d;
  }
};
// 256 bytes, 4 cache lines of 64: the normal (24), four points (224), the count and its padding
// (8). The narrow phase writes one per touching pair each step and the solvers read them all.
static_assert(sizeof(ContactManifold) == 4 * 64, "ContactManifold's size in cache lines: see the comment above");

// A touching (or, within the contact margin, nearly touching) pair. For a body against a plane,
// `a` is the plane's index and the normal is the plane's (collision/narrowphase/convex_plane.h).
struct Contact {
  enum class Kind { BodyBody, PlaneBody } kind = Kind::BodyBody;
  std::size_t a = 0, b = 0;
  // Which of the pair's manifolds (a body of any shape may touch another along several normals:
  // collision/narrowphase/sdf_contact.h; a compound's children each touch on their own:
  // compoundPart); part of the warm-start key, below 2^15.
  std::uint16_t part = 0;
  ContactManifold manifold;
  // The child shapes of a and b that touch (body/child_shape.h), whose materials the solvers
  // combine; 0 for a body of one shape and for a plane.
  std::uint16_t childA = 0, childB = 0;
};
// 296 bytes, 4.6 cache lines of 64: the kind (4 and 4 of padding), a and b (16), part (2 and 6
// of padding), the manifold (256), the children (4 and 4 of padding). With part and the children
// beside the kind it would be 288, but aggregate initialisers list the fields in this order
// ({kind, a, b, part, manifold}).
static_assert(!kStatedLayout || sizeof(Contact) == 296, "Contact's size: see the comment above");

// The part of a pair of compound children: distinct for every pair of children.
inline std::uint16_t compoundPart(std::size_t childA, std::size_t childB) {
  constexpr std::size_t kChildren = 128;  // body/child_shape.h kMaxCompoundChildren
  return static_cast<std::uint16_t>(childA * kChildren + childB);
}

}  // namespace rbsim
