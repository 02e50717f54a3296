#pragma once
// A contact after World::destroyBodies (body/body_removal.h): it follows its bodies to their new
// indices, wherever it is kept (the step's contacts, a sleeping island's), so that a removal
// touches only the contacts of the bodies it reached.
#include <cstddef>
#include <utility>
#include <vector>

#include "body/body_removal.h"
#include "rbsim/collision/contact.h"

namespace rbsim {

// False when the contact goes with a removed body (its partner's index before the removal, when
// it has one, into `touched`: it must wake). A pair in order (the lower index first) that a move
// turns round has its normal reversed (points are midway, unchanged), or, for a compound's or
// mesh ground's manifolds, whose part names their shapes in order, goes.
inline bool renumberContact(Contact& c, const BodyRemoval& removal, std::vector<std::size_t>& touched) {
  const bool pair = c.kind == Contact::Kind::BodyBody;
  if (!removal.involves(c.b) && !(pair && removal.involves(c.a))) return true;
  const auto turn = [&c](std::size_t, std::size_t) {
    if (c.part != 0) return false;
    std::swap(c.childA, c.childB);
    c.manifold.normal = -c.manifold.normal;
    return true;
  };
  return removal.replay(pair, c.a, c.b, turn, [&](std::size_t partner) { touched.push_back(partner); });
}

}  // namespace rbsim
