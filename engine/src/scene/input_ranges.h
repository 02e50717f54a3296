#pragma once
// The physical ranges a scene's lengths, speeds and accelerations must lie in. Each number in
// them is finite, but finite is not enough: a speed of 1e300 m/s passes the parser and then
// overflows a body's bounding box in its first step. Beyond these bounds no rigid-body scene is
// meaningful, so the parser refuses them naming the field, rather than the step diverging.
// The World's own tuning values (gravity, contact tolerances) are ranged by checkSettings.
#include "rbsim/settings/settings.h"

namespace rbsim {

// Positions, anchors and points on planes [m]. The contact tolerances (5 mm slop, millimetre
// margins) need positions resolved far below a millimetre; ulp(1e6 m) = 1.2e-10 m.
inline constexpr double kMaxCoordinate = 1e6;  // [m]
// Why, in the words of the messages that refuse a coordinate beyond it.
inline constexpr const char* kFarFromOrigin = "beyond it a double cannot resolve the contact tolerances";
// No body moves faster than light: a larger speed is a typo or an attempt to overflow.
inline constexpr double kMaxSpeed = 299'792'458.0;  // [m/s], c
// Masses and principal moments of inertia [kg, kg m^2], and their inverses, at most this: the
// solver multiplies a mass by an inverse mass (a pair's effective mass against one body's), so
// each within 1e+-150 keeps every such product inside a double's 1e+-308.
inline constexpr double kMaxMassScale = 1e150;
// Stiffer than any solid: ten times diamond's 1.2e12 Pa (steel is 2e11 Pa).
inline constexpr double kMaxYoungsModulus = 1e13;  // [Pa]

}  // namespace rbsim
