#pragma once
// The ranges of a kinematic motion (issue 56, item 5): no point of the body it drives may move
// faster than light, as no body's own velocity may (input_ranges.h, kMaxSpeed).
#include "rbsim/body/body_def.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/world/kinematic_motion.h"

namespace rbsim::scene_detail {

// Fails `m` (the "motion" block) naming the key whose motion is too fast: a pivot's surface speed
// |omega| (|x - pivot| + r), or between two keyframes (the body's start and the first key, and
// the jump back to the first key when it loops, at the time step `dt`) its path |dx| / dt plus its
// surface's turning angle r / dt, r the body's reach from its centre.
void checkMotionSpeeds(const JsonObject& m, const KinematicMotion& motion, const BodyDef& body, double dt);

}  // namespace rbsim::scene_detail
