#pragma once
// The physical ranges a scene's lengths, speeds and accelerations must lie in. Each number in
// them is finite, but finite is not enough: a speed of 1e300 m/s passes the parser and then
// overflows a body's bounding box in its first step. Beyond these bounds no rigid-body scene is
// meaningful, so the parser refuses them naming the field, rather than the step diverging.
// The World's own tuning values (gravity, contact tolerances) are ranged by checkSettings.
#include "rbsim/math/physical_ranges.h"  // kMaxCoordinate, kMaxSpeed, kMaxMassScale
#include "rbsim/settings/settings.h"

namespace rbsim {

// Stiffer than any solid: ten times diamond's 1.2e12 Pa (steel is 2e11 Pa).
inline constexpr double kMaxYoungsModulus = 1e13;  // [Pa]

}  // namespace rbsim
