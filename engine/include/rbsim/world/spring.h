#pragma once
// A damped spring from a world anchor to a point fixed in a body (seed 000 "particle systems":
// spring forces F = -k (|d| - rest) d/|d| - c v_rel along d). Accumulated each step with gravity.
#include <cstddef>

#include "rbsim/body/body_id.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct Spring {
  BodyId body;
  Vec3 anchor = Vec3::Zero();      // world frame [m]
  Vec3 point = Vec3::Zero();       // body frame, relative to the centre of mass [m]
  double stiffness = 0.0;          // k [N/m], >= 0
  double restLength = 0.0;         // [m], >= 0
  double damping = 0.0;            // c [N s/m], >= 0, along the spring only
};

}  // namespace rbsim
