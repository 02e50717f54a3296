#pragma once
// FNV-1a, 64-bit (Fowler, Noll and Vo), over the bit patterns of doubles: World::stateHash and the
// systems' hashes chain through it, so equal hashes mean bit for bit equal runs.
#include <cstdint>
#include <cstring>

namespace rbsim {

inline constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

inline std::uint64_t fnvMix(std::uint64_t hash, double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) {
    hash ^= (bits >> (8 * i)) & 0xffu;
    hash *= kFnvPrime;
  }
  return hash;
}

}  // namespace rbsim
