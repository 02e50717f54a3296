#include "particles/noise.h"

#include <cmath>

namespace rbsim {

namespace {

// SplitMix64's finaliser (Steele, Lea, Flood, "Fast splittable pseudorandom number generators",
// OOPSLA 2014): every input bit changes about half of the output bits.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double latticeValue(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t seed) {
  std::uint64_t h = mix(seed ^ static_cast<std::uint64_t>(x));
  h = mix(h ^ static_cast<std::uint64_t>(y));
  h = mix(h ^ static_cast<std::uint64_t>(z));
  return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;  // [-1, 1)
}

// The lattice index of a floored coordinate. Past 2^62 cells (or for a NaN or infinite sample
// point, which the system's divergence check reports) the cast to int64 would be undefined: the
// lattice repeats with that period instead (fmod is exact), and a non-finite point reads cell 0.
std::int64_t latticeIndex(double floored) {
  constexpr double kPeriod = 0x1.0p62;  // [cells]
  return std::isfinite(floored) ? static_cast<std::int64_t>(std::fmod(floored, kPeriod)) : 0;
}

double fade(double t) { return t * t * t * (t * (6.0 * t - 15.0) + 10.0); }

}  // namespace

double valueNoise(const Vec3& p, std::uint64_t seed) {
  const double fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const std::int64_t x = latticeIndex(fx), y = latticeIndex(fy), z = latticeIndex(fz);
  const double u = fade(p.x() - fx), v = fade(p.y() - fy), w = fade(p.z() - fz);
  double corner[2][2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) corner[i][j][k] = latticeValue(x + i, y + j, z + k, seed);
  const auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double x00 = lerp(corner[0][0][0], corner[1][0][0], u), x10 = lerp(corner[0][1][0], corner[1][1][0], u);
  const double x01 = lerp(corner[0][0][1], corner[1][0][1], u), x11 = lerp(corner[0][1][1], corner[1][1][1], u);
  return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

Vec3 noiseVector(const Vec3& p, double s, std::uint64_t seed) {
  // Time moves the sample point along this direction, not along an axis, so that no lattice
  // plane is crossed by all particles at once (which would pulse the whole field together).
  const Vec3 drift(1.0, 0.7, 0.3);  // [lattice cells per unit of s]
  const Vec3 q = p + s * drift;
  return {valueNoise(q, seed), valueNoise(q, seed + 1), valueNoise(q, seed + 2)};
}

}  // namespace rbsim
