#pragma once
// A one-byte summary of an interval for rejecting pair tests without reading either box.
// The line is cut into slabs of width w, numbered floor(x / w); slab k is bit k mod 8, and an
// interval sets the bits of the slabs it covers (all eight if it covers eight or more). Two
// closed intervals that overlap share a point x, so both cover slab floor(x / w): their masks
// share a bit. Masks with no common bit therefore prove the intervals apart; a common bit proves
// nothing (the slabs may be eight apart), and the caller then reads the boxes.
#include <cmath>
#include <cstdint>

namespace rbsim {

// invWidth = 1 / w [1/m], positive and finite; lo <= hi [m].
inline std::uint32_t slabMask(double lo, double hi, double invWidth) {
  constexpr double kExactInteger = 4503599627370496.0;  // 2^52: beyond it slab numbers are coarse
  constexpr std::uint32_t kAllSlabs = 0xffu;
  const double a = lo * invWidth, b = hi * invWidth;  // rounding keeps a <= b: monotone
  if (!(std::abs(a) < kExactInteger) || !(std::abs(b) < kExactInteger)) return kAllSlabs;
  // floor by truncation and correction: std::floor is a library call without SSE4.1.
  std::int64_t first = static_cast<std::int64_t>(a), last = static_cast<std::int64_t>(b);
  first -= static_cast<double>(first) > a;
  last -= static_cast<double>(last) > b;
  if (last - first >= 7) return kAllSlabs;
  const auto shift = static_cast<std::uint32_t>(first & 7);
  const std::uint32_t run = (2u << static_cast<std::uint32_t>(last - first)) - 1u;  // span + 1 ones
  return ((run << shift) | (run >> (8u - shift))) & kAllSlabs;
}

}  // namespace rbsim
