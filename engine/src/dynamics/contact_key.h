#pragma once
// What both contact solvers need to name a manifold across steps and to span its tangent plane.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#include "rbsim/math/types.h"
#include "rbsim/collision/contact.h"
#include "body/body_removal.h"

namespace rbsim {

// Kind (1 bit), the manifold's part of the pair (15 bits: a compound's pair of children,
// contact.h compoundPart), then a and b (24 bits each: 16.7 M bodies, beyond what a step can
// hold): the key under which a manifold's impulses are kept for the next step's warm start.
inline std::uint64_t pairKey(const Contact& c) {
  const std::uint64_t kind = c.kind == Contact::Kind::PlaneBody ? 1u : 0u;
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 24) - 1;
  return (kind << 63) | (static_cast<std::uint64_t>(c.part & 0x7fff) << 48) |
         ((static_cast<std::uint64_t>(c.a) & kIndexMask) << 24) | (static_cast<std::uint64_t>(c.b) & kIndexMask);
}

// After World::destroyBodies (body/body_removal.h): the warm starts of the removed bodies'
// manifolds go, and those of the moved bodies' follow them to their new indices; every other
// manifold keeps its warm start, where forgetting them all cost a resting stack a cold step (its
// boxes jumping to 5 cm/s) for each body removed anywhere. A pair in order (the lower index
// first) that a move turns round is handed to `turn(entry, moved, partner)` (indices before the
// removal), which rewrites the entry for the moved body as the first (its points into the
// partner's frame, its impulses' signs) or returns false to let it start cold (as
// CollisionPipeline::removeBodies turns the pair's contact). `Entry` has a `key` made by pairKey;
// the list stays sorted by it.
template <class Entry, class Turn>
void renumberCache(std::vector<Entry>& cache, const BodyRemoval& removal, Turn&& turn) {
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 24) - 1;
  const auto byKey = [](const Entry& x, const Entry& y) { return x.key < y.key; };
  // The entries left as they were stay in order; the renamed few are sorted and merged back in:
  // linear in the list for the whole batch, not a sort of the whole list.
  std::vector<Entry> renamed;
  std::size_t kept = 0;
  for (Entry& entry : cache) {
    const bool plane = (entry.key >> 63) != 0;  // a is a plane's index, not a body's
    std::size_t a = (entry.key >> 24) & kIndexMask, b = entry.key & kIndexMask;
    if (!removal.involves(b) && (plane || !removal.involves(a))) {
      if (&cache[kept] != &entry) cache[kept] = std::move(entry);  // those before the first change stay put
      ++kept;
      continue;
    }
    // Only a pair of single shapes turns (part 0): a compound's or a mesh ground's part names
    // its shapes in order, and those manifolds start cold.
    const bool single = ((entry.key >> 48) & 0x7fff) == 0;
    const auto turnEntry = [&](std::size_t moved, std::size_t partner) { return single && turn(entry, moved, partner); };
    if (!removal.replay(!plane, a, b, turnEntry, [](std::size_t) {})) continue;
    entry.key = (entry.key & ~((kIndexMask << 24) | kIndexMask)) | (std::uint64_t{a} << 24) | std::uint64_t{b};
    renamed.push_back(std::move(entry));
  }
  cache.resize(kept);
  std::sort(renamed.begin(), renamed.end(), byKey);
  cache.insert(cache.end(), std::make_move_iterator(renamed.begin()), std::make_move_iterator(renamed.end()));
  std::inplace_merge(cache.begin(), cache.begin() + static_cast<std::ptrdiff_t>(kept), cache.end(), byKey);
}

// A turned pair's anchors (renumberCache): from the moved body's frame, where they were as the
// pair's second body, into the partner's, which is second now.
template <class Body, std::size_t N>
void anchorsToPartner(std::array<Vec3, N>& points, int count, const Body& moved, const Body& partner) {
  for (int j = 0; j < count; ++j) points[j] = partner.rotation().transpose() * (moved.bodyToWorld(points[j]) - partner.position());
}

// Two unit tangents completing the normal to a right-handed basis.
inline void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  // Some component of a unit vector is at least 1/sqrt(3); crossing with x while |n.x| is below
  // that keeps the cross product well away from zero.
  const double oneOverSqrt3 = 1.0 / std::sqrt(3.0);
  const Vec3 seed = std::abs(n.x()) < oneOverSqrt3 ? Vec3::UnitX() : Vec3::UnitY();
  t1 = n.cross(seed).normalized();
  t2 = n.cross(t1);
}

}  // namespace rbsim
