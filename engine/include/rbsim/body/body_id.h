#pragma once
// A handle to a World's body that outlives index changes (Box2D v3's b2BodyId, Jolt's BodyID):
// the slot it names and the slot's generation when it was made. Destroying a body bumps its
// slot's generation, so a handle kept past the destruction is recognised as stale, even once the
// slot holds a new body, and never reaches another body.
#include <cstdint>

namespace rbsim {

struct BodyId {
  std::uint32_t slot = UINT32_MAX;  // UINT32_MAX: no body
  std::uint32_t generation = 0;
  friend bool operator==(const BodyId& a, const BodyId& b) { return a.slot == b.slot && a.generation == b.generation; }
  friend bool operator!=(const BodyId& a, const BodyId& b) { return !(a == b); }
};

}  // namespace rbsim
