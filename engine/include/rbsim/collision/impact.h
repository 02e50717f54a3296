#pragma once
// A fast body stopped at its time of impact by continuous collision detection (stage
// ContinuousCollision; engine/src/world/continuous_collision.h).
#include <cstddef>

#include "rbsim/math/types.h"

namespace rbsim {

struct Impact {
  std::size_t body = 0;                   // index into World::bodies()
  double fraction = 1.0;                  // s in [0, 1] of the step at which it stopped
  Vec3 unstoppedPosition = Vec3::Zero();  // where the step would have taken it [m]
  Quat unstoppedOrientation = Quat::Identity();
};

}  // namespace rbsim
