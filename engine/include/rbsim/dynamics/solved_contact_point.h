#pragma once
// One contact point after a contact solver ran, as both solvers report it (World::contactPoints).
#include <cstddef>

#include "rbsim/math/types.h"

namespace rbsim {

// Body 1 is the contact's body B, body 2 its body A or plane, so the normal (the manifold's, from
// A to B) points towards body 1, as seed 000's N does.
struct SolvedContactPoint {
  std::size_t contact = 0;          // index into World::contacts()
  Vec3 position = Vec3::Zero();     // world [m]
  Vec3 normal = Vec3::UnitY();      // unit, towards body 1
  double depth = 0.0;               // [m], < 0 for a speculative contact
  double normalImpulse = 0.0;       // j_N >= 0 this step [N s]
  Vec3 frictionImpulse = Vec3::Zero();  // the point's share of the friction this step [N s]
  double approachVelocity = 0.0;    // u_rel,N before the solve [m/s]
  double normalVelocity = 0.0;      // u_rel,N after it [m/s]
  bool sticking = false;            // static friction held: inside the mu_s cone

  Vec3 impulse() const { return normalImpulse * normal + frictionImpulse; }  // on body 1
};
// 120 bytes, under 2 cache lines of 64: the contact's index (8), three vectors (72), four doubles
// (32), the flag and 7 of padding. The solvers write one per contact point each step.
static_assert(sizeof(SolvedContactPoint) == 120, "SolvedContactPoint's size: see the comment above");

}  // namespace rbsim
