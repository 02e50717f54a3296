#pragma once
// A contact after World::destroyBodies (body/body_removal.h): it follows its bodies to their new
// indices, wherever it is kept (the step's contacts, a sleeping island's), so that a removal
// touches only the contacts of the bodies it reached.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "body/body_removal.h"
#include "rbsim/collision/contact.h"

namespace rbsim {

// False when the contact goes with a removed body (its partner's index before the removal, when
// it has one that stays, into `touched`: it must wake). Otherwise its bodies take their indices
// after the removal, in the same order: a pair is ordered by the bodies' stable keys
// (CollisionPipeline::bodiesOf), which a removal leaves as they were, so it never turns round.
inline bool renumberContact(Contact& c, const BodyRemoval& removal, std::vector<std::size_t>& touched) {
  const bool pair = c.kind == Contact::Kind::BodyBody;
  const std::uint32_t b = removal.newIndex(c.b);
  const std::uint32_t a = pair ? removal.newIndex(c.a) : static_cast<std::uint32_t>(c.a);
  if (a == BodyRemoval::kGone || b == BodyRemoval::kGone) {
    if (pair && a != BodyRemoval::kGone) touched.push_back(c.a);
    if (pair && b != BodyRemoval::kGone) touched.push_back(c.b);
    return false;
  }
  c.a = a;
  c.b = b;
  return true;
}

}  // namespace rbsim
