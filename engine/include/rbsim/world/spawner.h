#pragma once
// Bodies born and removed while the World steps (issue 40; Box3D's rain benchmark creates and
// destroys its ragdolls as it runs): a spawner adds copies of a prototype body in bursts at a
// period, each drawn from a seeded generator inside a region, and a kill volume removes the
// bodies that leave it (fallen off the world). Both act in stage SpawnAndRemove, at the start of
// a step. A spawner may instead add presets (ragdolls, world/ragdoll.h), several at fixed offsets
// from each drawn point, and may remove what it added once it reaches an age (Box3D's rain drops
// and clears a column of ragdoll groups at a time).
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rbsim/body/body_def.h"
#include "rbsim/body/body_id.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/math/types.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/world/ragdoll.h"

namespace rbsim {

class World;

struct SpawnerDef {
  std::string name = "spawn";  // its bodies are named <name>_<n>, n counting from 0 over the run
  BodyDef prototype;           // what every body is, but its pose and velocities
  // Set: every copy is this figure instead of the prototype, its feet at the drawn point, named
  // <name>_<n> (bones <name>_<n>_<bone>), turned and moving as drawn (no spin).
  std::optional<RagdollDef> ragdoll;
  int count = 1;               // points drawn per burst, >= 1
  // One copy at each offset from every drawn point (world frame, not turned) [m]: a burst adds
  // count x offsets.size() copies.
  std::vector<Vec3> offsets{Vec3::Zero()};
  // Copies are removed this long after their burst (a ragdoll with its joints) [s]; infinity: kept.
  double lifetime = std::numeric_limits<double>::infinity();
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
// The same, and the period against the World's time step (checkSpawnPeriod): addSpawner's.
std::string checkSpawner(const SpawnerDef& def, double timeStep);

// A period shorter than the time step brings several bursts in one step, all at that step's
// instant: period 1e-9 s made 16.7 million bursts in a step of 1/60 s. A burst a step at most;
// more bodies at once are a larger count. Relative slack on the comparison [1]: a period written
// as 1/60 s to ten digits still counts as one step of 1/60 s.
constexpr double kSpawnPeriodSlack = 1e-9;
// Empty when at most one burst falls in a step of `timeStep` [s]; otherwise "period: ...".
std::string checkSpawnPeriod(double period, double timeStep);

// Of `bursts` made in all every `period` [s], the most alive at once when each lives `lifetime`
// [s] (infinity: all): ceil(lifetime / period) + 1, ceil and not floor since lifetime / period may
// round below a whole number the burst times reach. The budgets count with it.
double burstsAliveAtOnce(double bursts, double lifetime, double period);

// A spawner as the World keeps it: its def, its generator and how far it has got.
struct Spawner {
  SpawnerDef def;
  UniformRandom random{1};
  std::uint64_t bursts = 0;   // bursts so far
  std::uint64_t spawned = 0;  // copies so far (the next name's number)
  // With a finite lifetime: the bursts not yet removed, oldest first, each with its bodies.
  struct Burst {
    double time = 0.0;  // [s]
    std::vector<BodyId> bodies;
  };
  std::deque<Burst> alive;
  double nextTime() const { return def.start + static_cast<double>(bursts) * def.period; }
};

// Where and how one drawn point's copies start: the region's point, a turn of the prototype (or
// figure), the linear and angular velocities.
struct SpawnDraw {
  Vec3 position = Vec3::Zero();
  Quat turn = Quat::Identity();
  Vec3 velocity = Vec3::Zero(), angularVelocity = Vec3::Zero();
};
SpawnDraw drawPoint(Spawner& spawner);
// The next copy of the prototype body (or of the figure) at `offset` from the drawn point, named in turn.
BodyDef spawnBody(Spawner& spawner, const SpawnDraw& draw, const Vec3& offset);
RagdollDef spawnRagdoll(Spawner& spawner, const SpawnDraw& draw, const Vec3& offset);

// A World's spawners and kill volume: free functions over World, as ragdolls (addRagdoll) and
// kinematic motions are (docs/architecture.md, "The World's surface"); stage SpawnAndRemove runs them.
// Bodies born while the World steps: copies of def.prototype in bursts, from the step at or after
// def.start; returns the spawner's index in spawners(world). Throws std::invalid_argument on a bad
// def (checkSpawner with the World's time step), and on a ragdoll spawner under a solver other
// than the soft step.
std::size_t addSpawner(World& world, const SpawnerDef& def);
const std::vector<Spawner>& spawners(const World& world);
// Bodies whose centre of mass is outside `volume` at the start of a step are destroyed (static
// ones too). An empty box removes the volume. Throws std::invalid_argument on a box with a NaN.
void setKillVolume(World& world, const Aabb& volume);
const Aabb& killVolume(const World& world);
// What stage SpawnAndRemove did in the last step: the bodies it added (valid ids) and the ids of
// those it removed (stale now).
const std::vector<BodyId>& spawnedBodies(const World& world);
const std::vector<BodyId>& removedBodies(const World& world);

}  // namespace rbsim
