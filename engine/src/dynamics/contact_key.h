#pragma once
// What both contact solvers need to name a manifold across steps and to span its tangent plane.
#include <cmath>
#include <cstdint>

#include "rbsim/math/types.h"
#include "rbsim/collision/contact.h"

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
