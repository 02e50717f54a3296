#pragma once
// The crowd the throughput and stage-skip benchmarks step: boxes of random size (so no two share
// a mesh), pose, velocity and spin, spread over a 200 m cube so that none touch. One generator,
// so both benchmarks measure the same kind of body.
#include <cstdint>
#include <memory>
#include <random>

#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/world.h"

namespace rbsim::bench {

inline constexpr double kMaxSpeed = 5.0;     // [m/s] per component: far above the sleep speeds
inline constexpr double kMaxSpin = 10.0;     // [rad/s] per component
inline constexpr double kMinExtent = 0.1;    // [m] box edge
inline constexpr double kMaxExtent = 1.0;    // [m]
inline constexpr double kDensity = 1000.0;   // [kg/m^3], water
inline constexpr double kHalfSpread = 100.0; // [m] half the side of the cube the boxes fill

// Adds `count` boxes to `world`; with moving = false they start at rest.
inline void addRandomBoxes(World& world, int count, std::uint64_t seed, bool moving = true) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), extent(kMinExtent, kMaxExtent);
  for (int i = 0; i < count; ++i) {
    const Vec3 size(extent(rng), extent(rng), extent(rng));
    BodyDef def;
    def.mesh = std::make_shared<const Mesh>(makeBox(size));
    def.mass = kDensity * size.prod();
    def.inertiaBody = cuboidInertia(def.mass, size);
    def.position = kHalfSpread * Vec3(unit(rng), unit(rng), unit(rng));
    def.orientation = Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    if (moving) {
      def.velocity = kMaxSpeed * Vec3(unit(rng), unit(rng), unit(rng));
      def.angularVelocity = kMaxSpin * Vec3(unit(rng), unit(rng), unit(rng));
    }
    world.addBody(def);
  }
}

}  // namespace rbsim::bench
