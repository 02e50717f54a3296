#pragma once
// Reducing many contact candidates to a manifold of at most kMaxManifoldPoints (Gregorius,
// "Robust Contact Creation for Physics Simulations", GDC 2015): keep the deepest point, then the
// point farthest from it, then the one maximising the triangle's area, then the one adding the
// most area to that triangle. Areas and distances are measured in the contact plane.
#include <cstddef>
#include <vector>

#include "rbsim/collision/contact.h"
#include "rbsim/math/types.h"

namespace rbsim {

// A candidate joins the manifold only if it lies further than this [m] from what is already
// chosen: from the first point, from the line of the first two, outside an edge of the triangle.
// Duplicates and collinear extras are thereby dropped.
inline constexpr double kReductionTolerance = 1e-9;

// The manifold (normal = `normal`, unit, from A to B) of at most 4 of the candidates.
ContactManifold reduceContacts(const ContactPoint* candidates, std::size_t count, const Vec3& normal);
inline ContactManifold reduceContacts(const std::vector<ContactPoint>& candidates, const Vec3& normal) {
  return reduceContacts(candidates.data(), candidates.size(), normal);
}

}  // namespace rbsim
