#pragma once
// Fast marching (seed 000 "Fast Marching Method"): fills the unsigned distance of every grid point
// outward from the Black points whose exact distances are known.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rbsim/geometry/grid_lattice.h"

namespace rbsim {

// Point labels of the seed: Black (final), Red (tentative, on the heap), White (untouched).
enum class MarchLabel : std::uint8_t { White, Red, Black };

// On entry `distance` holds the exact distance of every Black point in `labels`; on return every
// point is Black with its distance. Each Red point's estimate solves the first-order upwind
// equation sum over axes of ((d - a_axis)_+)^2 = h^2 using, per axis, the smaller Black neighbour
// a_axis; a binary heap (lazy deletion of stale entries, ties broken by index, so the result is
// deterministic) makes it O(N log N). Returns the number of points marched.
std::size_t fastMarch(const GridLattice& shape, std::vector<MarchLabel>& labels,
                      std::vector<double>& distance);

}  // namespace rbsim
