// Stage SpawnAndRemove (world/spawner.h): bursts past their lifetime and bodies out of the kill
// volume removed, then the spawners' due bursts added.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rbsim/world/ragdoll.h"
#include "rbsim/world/world.h"
#include "world/world_access.h"

namespace rbsim {

std::string checkSpawner(const SpawnerDef& def) {
  if (def.count < 1) return "count: expected at least one body per burst";
  if (!(def.start >= 0.0) || !std::isfinite(def.start)) return "start: expected a finite time >= 0 s";
  if (!(def.period > 0.0) || !std::isfinite(def.period)) return "period: expected a finite time > 0 s";
  if (!(def.end > def.start)) return "end: expected a time after start";
  if (!def.regionMin.allFinite() || !def.regionMax.allFinite() || !(def.regionMin.array() <= def.regionMax.array()).all()) {
    return "region: expected finite corners with min <= max along every axis";
  }
  if (!(def.speedMin >= 0.0 && def.speedMin <= def.speedMax && std::isfinite(def.speedMax))) {
    return "speed: expected 0 <= min <= max, finite";
  }
  if (!(def.spinMin >= 0.0 && def.spinMin <= def.spinMax && std::isfinite(def.spinMax))) {
    return "angular_speed: expected 0 <= min <= max, finite";
  }
  if (def.offsets.empty()) return "offsets: expected at least one offset (0, 0, 0: at the drawn point)";
  for (const Vec3& offset : def.offsets) {
    if (!offset.allFinite()) return "offsets: expected finite offsets [m]";
  }
  if (!(def.lifetime > 0.0)) return "lifetime: expected a time > 0 s (infinity: kept)";
  if (def.ragdoll) {
    if (def.spinMax > 0.0) return "angular_speed: a ragdoll is spawned without spin; expected none";
    return {};
  }
  if (!def.prototype.mesh) return "body: no mesh";
  return {};
}

namespace {
// Digits to print a count of bursts whole (16666667, not 1.66667e+07), and the stream's default.
constexpr int kWholeDigits = 15;
constexpr int kDefaultDigits = 6;
}  // namespace

double burstsAliveAtOnce(double bursts, double lifetime, double period) {
  return std::isfinite(lifetime) ? std::min(bursts, std::ceil(lifetime / period) + 1.0) : bursts;
}

std::string checkSpawnPeriod(double period, double timeStep) {
  if (period >= timeStep * (1.0 - kSpawnPeriodSlack)) return {};
  std::ostringstream problem;
  problem << "period: " << period << " s is shorter than the time step, " << timeStep << " s, and would bring "
          << std::setprecision(kWholeDigits) << std::ceil(timeStep / period) << std::setprecision(kDefaultDigits)
          << " bursts in one step, all at its instant; expected a period >= "
          << timeStep << " s (a burst a step at most: raise count for more bodies at once)";
  return problem.str();
}

std::string checkSpawner(const SpawnerDef& def, double timeStep) {
  const std::string problem = checkSpawner(def);
  return problem.empty() ? checkSpawnPeriod(def.period, timeStep) : problem;
}

SpawnDraw drawPoint(Spawner& spawner) {
  const SpawnerDef& d = spawner.def;
  UniformRandom& random = spawner.random;
  SpawnDraw draw;
  // One draw a statement: C++ leaves the order of a call's arguments (and of a product's operands)
  // unspecified, and GCC and clang differ, so each scene would spawn elsewhere with each compiler
  // (issue 59: the browser build is clang's). The order is the one GCC gave the single
  // expressions this replaced, right to left, so the native program's scenes are unchanged.
  const double z = random.between(d.regionMin.z(), d.regionMax.z());
  const double y = random.between(d.regionMin.y(), d.regionMax.y());
  const double x = random.between(d.regionMin.x(), d.regionMax.x());
  draw.position = Vec3(x, y, z);
  if (d.randomOrientation) draw.turn = random.rotation();
  const Vec3 direction = random.direction();
  draw.velocity = random.between(d.speedMin, d.speedMax) * direction;
  const Vec3 axis = random.direction();
  draw.angularVelocity = random.between(d.spinMin, d.spinMax) * axis;
  return draw;
}

BodyDef spawnBody(Spawner& spawner, const SpawnDraw& draw, const Vec3& offset) {
  BodyDef def = spawner.def.prototype;
  def.name = spawner.def.name + "_" + std::to_string(spawner.spawned++);
  def.position = draw.position + offset;
  def.orientation = draw.turn * def.orientation;
  def.velocity = draw.velocity;
  def.angularVelocity = draw.angularVelocity;
  return def;
}

RagdollDef spawnRagdoll(Spawner& spawner, const SpawnDraw& draw, const Vec3& offset) {
  RagdollDef def = *spawner.def.ragdoll;
  def.name = spawner.def.name + "_" + std::to_string(spawner.spawned++);
  def.position = draw.position + offset;
  def.orientation = draw.turn * def.orientation;
  def.velocity = draw.velocity;
  return def;
}

std::size_t addSpawner(World& world, const SpawnerDef& def) {
  const Settings& settings = world.settings();
  const std::string problem = checkSpawner(def, settings.timeStep);
  if (!problem.empty()) throw std::invalid_argument("spawner '" + def.name + "': " + problem);
  if (def.ragdoll && settings.solver != Settings::ContactSolverMethod::SoftStep) {
    throw std::invalid_argument("spawner '" + def.name + "': ragdoll: a ragdoll's joints need the soft-step solver");
  }
  // The prototype's (or the figure's bodies' and joints') own checks, now rather than at the first
  // burst, in the middle of a step.
  if (def.ragdoll) {
    World probe(settings);
    static_cast<void>(addRagdoll(probe, *def.ragdoll));
  } else {
    static_cast<void>(RigidBody(def.prototype));
  }
  Spawner spawner;
  spawner.def = def;
  spawner.random = UniformRandom(def.seed);
  // A spawner added late starts with its next burst, not with all those it missed.
  const double now = world.time();
  if (def.start < now) spawner.bursts = static_cast<std::uint64_t>(std::ceil((now - def.start) / def.period));
  std::vector<Spawner>& spawners = WorldAccess::spawners(world);
  spawners.push_back(std::move(spawner));
  return spawners.size() - 1;
}

const std::vector<Spawner>& spawners(const World& world) { return WorldAccess::spawners(world); }

void setKillVolume(World& world, const Aabb& volume) {
  if (volume.min.hasNaN() || volume.max.hasNaN()) throw std::invalid_argument("kill volume: a corner is not a number");
  WorldAccess::killVolume(world) = volume;
}

const Aabb& killVolume(const World& world) { return WorldAccess::killVolume(world); }
const std::vector<BodyId>& spawnedBodies(const World& world) { return WorldAccess::spawnedNow(world); }
const std::vector<BodyId>& removedBodies(const World& world) { return WorldAccess::removedNow(world); }

// Half a step early: a burst due at 1.0 s happens at the step starting then, not one later for
// the rounding of 60 x (1/60); an age likewise.
double World::spawnDueTime() const { return time() + 0.5 * settings_.timeStep; }

// A static body never leaves the volume, so never goes: a ground whose centre lies outside it
// was removed at the first step (issue 56, item 5).
bool World::outsideKillVolume(std::size_t i) const {
  const Vec3& x = table_->bodies[i].position();
  return !killVolume_.empty() && !table_->bodies[i].isStatic() &&
         !((x.array() >= killVolume_.min.array()).all() && (x.array() <= killVolume_.max.array()).all());
}

bool World::spawnDue() const {
  const double due = spawnDueTime();
  return std::any_of(spawners_.begin(), spawners_.end(), [due](const Spawner& spawner) {
    return spawner.nextTime() <= due && spawner.nextTime() < spawner.def.end;
  });
}

bool World::removalDue() const {
  const double due = spawnDueTime();
  for (const Spawner& spawner : spawners_) {
    if (!spawner.alive.empty() && spawner.alive.front().time + spawner.def.lifetime <= due) return true;
  }
  for (std::size_t i = 0; i < table_->bodies.size() && !killVolume_.empty(); ++i) {
    if (outsideKillVolume(i)) return true;
  }
  return false;
}

void World::spawnAndRemove() {
  const double due = spawnDueTime();
  std::vector<BodyId> expired;
  for (Spawner& spawner : spawners_) {
    while (!spawner.alive.empty() && spawner.alive.front().time + spawner.def.lifetime <= due) {
      for (const BodyId id : spawner.alive.front().bodies) {
        if (isValid(id)) expired.push_back(id);  // not if the kill volume or the user took it already
      }
      spawner.alive.pop_front();
    }
  }
  if (!killVolume_.empty()) {
    std::vector<char> listed(table_->bodies.size(), 0);
    for (const BodyId id : expired) listed[indexOf(id)] = 1;
    for (std::size_t i = 0; i < table_->bodies.size(); ++i) {
      if (!listed[i] && outsideKillVolume(i)) expired.push_back(idAt(i));
    }
  }
  // One batch: destroying them one at a time walked every contact and warm start for each body
  // (a burst of 1e5 resting boxes took about 150 s).
  destroyBodies(expired);
  removedNow_.insert(removedNow_.end(), expired.begin(), expired.end());
  for (Spawner& spawner : spawners_) {
    while (spawner.nextTime() <= due && spawner.nextTime() < spawner.def.end) {
      Spawner::Burst burst{spawner.nextTime(), {}};
      for (int k = 0; k < spawner.def.count; ++k) {
        const SpawnDraw draw = drawPoint(spawner);
        for (const Vec3& offset : spawner.def.offsets) {
          if (spawner.def.ragdoll) {
            const Ragdoll ragdoll = addRagdoll(*this, spawnRagdoll(spawner, draw, offset));
            burst.bodies.insert(burst.bodies.end(), ragdoll.bodies.begin(), ragdoll.bodies.end());
          } else {
            burst.bodies.push_back(addBody(spawnBody(spawner, draw, offset)));
          }
        }
      }
      spawnedNow_.insert(spawnedNow_.end(), burst.bodies.begin(), burst.bodies.end());
      if (std::isfinite(spawner.def.lifetime)) spawner.alive.push_back(std::move(burst));
      ++spawner.bursts;
    }
  }
}

}  // namespace rbsim
