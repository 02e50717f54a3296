#pragma once
// What both contact solvers need to name a manifold across steps and to span its tangent plane.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rbsim/math/types.h"
#include "rbsim/collision/contact.h"

namespace rbsim {

// Kind (1 bit), the manifold's part of the pair (15 bits: a compound's pair of children,
// contact.h compoundPart), then a and b (24 bits each: 16.7 M bodies, beyond what a step can
// hold): the key under which a manifold's impulses are kept for the next step's warm start. The
// bodies are named by their stable keys (`keys`, per body index: the BodyId slot, World's
// bodyKeys), not their indices, so that a removal, which moves bodies to new indices, leaves every
// other pair's key as it was (Box2D v3 keys contacts by shape ids: contact.c b2AddContact); a
// plane keeps its index.
inline std::uint64_t pairKey(Contact::Kind kind, std::uint16_t part, std::uint64_t a, std::uint64_t b) {
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 24) - 1;
  return (std::uint64_t{kind == Contact::Kind::PlaneBody} << 63) | (static_cast<std::uint64_t>(part & 0x7fff) << 48) |
         ((a & kIndexMask) << 24) | (b & kIndexMask);
}
inline std::uint64_t pairKey(const Contact& c, const std::vector<std::uint32_t>& keys) {
  return pairKey(c.kind, c.part, c.kind == Contact::Kind::PlaneBody ? c.a : keys[c.a], keys[c.b]);
}

// Whether a warm start's key names one of `removed` (sorted body keys): it goes with the body, as
// its slot may name another body later.
inline bool namesRemoved(std::uint64_t key, const std::vector<std::uint32_t>& removed) {
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 24) - 1;
  const bool plane = (key >> 63) != 0;
  const auto listed = [&](std::uint64_t k) {
    return std::binary_search(removed.begin(), removed.end(), static_cast<std::uint32_t>(k));
  };
  return listed(key & kIndexMask) || (!plane && listed((key >> 24) & kIndexMask));
}

// After World::destroyBodies: the warm starts naming a removed body go; every other keeps its key
// and its place (keys are stable), so the list stays sorted.
template <class Entry>
void dropRemoved(std::vector<Entry>& cache, const std::vector<std::uint32_t>& removed) {
  cache.erase(std::remove_if(cache.begin(), cache.end(), [&](const Entry& e) { return namesRemoved(e.key, removed); }),
              cache.end());
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
