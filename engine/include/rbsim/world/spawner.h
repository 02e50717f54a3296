#pragma once
// Bodies born and removed while the World steps (issue 40; Box3D's rain benchmark creates and
// destroys its ragdolls as it runs): a spawner adds copies of a prototype body in bursts at a
// period, each drawn from a seeded generator inside a region, and a kill volume removes the
// bodies that leave it (fallen off the world). Both act in stage SpawnAndRemove, at the start of
// a step.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/body/body_id.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/math/types.h"
#include "rbsim/math/uniform_random.h"

namespace rbsim {

struct SpawnerDef {
  std::string name = "spawn";  // its bodies are named <name>_<n>, n counting from 0 over the run
  BodyDef prototype;           // what every body is, but its pose and velocities
  int count = 1;               // bodies per burst, >= 1
  double start = 0.0;          // time of the first burst [s], >= 0
  double period = 1.0;         // between bursts [s], > 0
  double end = std::numeric_limits<double>::infinity();  // no burst at or after this [s]
  Vec3 regionMin = Vec3::Zero(), regionMax = Vec3::Zero();  // centres of mass drawn in this box [m]
  double speedMin = 0.0, speedMax = 0.0;  // |v| drawn in [min, max], direction uniform [m/s]
  double spinMin = 0.0, spinMax = 0.0;    // |omega| likewise [rad/s]
  bool randomOrientation = true;          // the prototype's orientation turned uniformly
  std::uint64_t seed = 1;
};

// Empty when the def is usable; otherwise what is wrong, naming the field.
std::string checkSpawner(const SpawnerDef& def);

// A spawner as the World keeps it: its def, its generator and how far it has got.
struct Spawner {
  SpawnerDef def;
  UniformRandom random{1};
  std::uint64_t bursts = 0;   // bursts so far
  std::uint64_t spawned = 0;  // bodies so far (the next name's number)
  double nextTime() const { return def.start + static_cast<double>(bursts) * def.period; }
};

// The next body of the spawner: the prototype drawn where and how the def says, named in turn.
BodyDef drawSpawn(Spawner& spawner);

}  // namespace rbsim
