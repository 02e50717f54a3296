#pragma once
// The physical ranges a body's lengths, speeds and masses must lie in, wherever they come from: a
// scene file (the loader's checks, engine/src/scene/input_ranges.h) or a change to a running World
// (setBodyMass, setJointLimits). Each number in them is finite, but finite is not enough:
// a speed of 1e300 m/s passes a finiteness check and then overflows a body's bounding box in its
// first step. Beyond these bounds no rigid-body scene is meaningful.

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
// What a mass or moment beyond it is told, after the values.
inline constexpr const char* kMassScaleExpectation =
    "expected the mass, the moments and their inverses each within 1e+-150 (the solver multiplies one by another)";

// A mass [kg] or principal moment [kg m^2] and its inverse both within kMaxMassScale.
inline bool withinMassScale(double x) { return x <= kMaxMassScale && 1.0 / x <= kMaxMassScale; }

}  // namespace rbsim
