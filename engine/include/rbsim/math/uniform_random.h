#pragma once
// A seeded generator of uniform doubles, shared by scene spawn blocks and particle emitters, so
// that a scene describes the same bodies and the same particles on every machine.
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

#include "rbsim/math/types.h"

namespace rbsim {

// Uniform doubles in [0, 1) from the top 53 bits: std::uniform_real_distribution is
// implementation-defined, and a scene must give the same result with every standard library.
class UniformRandom {
 public:
  explicit UniformRandom(std::uint64_t seed) : engine_(seed) {}
  double next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double between(double lo, double hi) { return lo + (hi - lo) * next(); }
  Vec3 direction() {  // uniform on the unit sphere (Archimedes: z uniform in [-1, 1])
    const double z = between(-1.0, 1.0), phi = between(0.0, 2.0 * kPi);
    const double r = std::sqrt(1.0 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  Quat rotation() {  // uniform over SO(3) (Shoemake 1992, "Uniform random rotations")
    const double u1 = next(), u2 = between(0.0, 2.0 * kPi), u3 = between(0.0, 2.0 * kPi);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return Quat(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
  }

 // The generator's whole state as the standard's text form (std::mersenne_twister_engine's
  // operator<<), for a World snapshot; setState returns false, changing nothing, on text that is
  // not one.
  std::string state() const {
    std::ostringstream out;
    out << engine_;
    return out.str();
  }
  bool setState(const std::string& text) {
    std::istringstream in(text);
    std::mt19937_64 engine;
    in >> engine;
    if (in.fail()) return false;
    engine_ = engine;
    return true;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace rbsim
