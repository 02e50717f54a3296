#pragma once
// Smooth value noise for wind turbulence (seed 000's homework lists wind, smoke and leaves): a
// pseudo-random value in [-1, 1] at every integer lattice point, blended between the 8 corners
// of the lattice cell with the quintic fade 6t^5 - 15t^4 + 10t^3 (Perlin, "Improving noise",
// SIGGRAPH 2002), so the field and its gradient are continuous. Pure function of the point and
// the seed: runs are reproducible.
#include <cstdint>

#include "rbsim/math/types.h"

namespace rbsim {

// Scalar noise at p (lattice spacing 1) in [-1, 1].
double valueNoise(const Vec3& p, std::uint64_t seed);

// Three independent noise fields at p and time coordinate s (added along a fixed diagonal, so
// the pattern both drifts and changes), each component in [-1, 1].
Vec3 noiseVector(const Vec3& p, double s, std::uint64_t seed);

}  // namespace rbsim
