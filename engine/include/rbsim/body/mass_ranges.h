#pragma once
// The checks of a body's mass properties given by hand (setBodyMass, Python's
// World.set_body), in the scene loader's words and ranges (math/physical_ranges.h): each empty
// when the value is usable, otherwise what was expected.
#include <string>

#include "rbsim/math/types.h"

namespace rbsim {

std::string massProblem(double mass);  // [kg]: finite and > 0
// [kg m^2] about the centre of mass, body frame: finite, symmetric, positive definite.
std::string inertiaProblem(const Mat3& inertia);
// The mass, the principal moments and their inverses within kMaxMassScale (reported against the
// mass, as the scene reports it); for a usable mass and inertia.
std::string massScaleProblem(double mass, const Mat3& inertia);

}  // namespace rbsim
