// Stage SpawnAndRemove (world/spawner.h): the kill volume's removals, then the spawners' bursts.
#include <cmath>
#include <stdexcept>
#include <string>

#include "rbsim/world/world.h"

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
  if (!def.prototype.mesh) return "body: no mesh";
  return {};
}

BodyDef drawSpawn(Spawner& spawner) {
  const SpawnerDef& d = spawner.def;
  UniformRandom& random = spawner.random;
  BodyDef def = d.prototype;
  def.name = d.name + "_" + std::to_string(spawner.spawned++);
  def.position = Vec3(random.between(d.regionMin.x(), d.regionMax.x()), random.between(d.regionMin.y(), d.regionMax.y()),
                      random.between(d.regionMin.z(), d.regionMax.z()));
  if (d.randomOrientation) def.orientation = random.rotation() * d.prototype.orientation;
  def.velocity = random.between(d.speedMin, d.speedMax) * random.direction();
  def.angularVelocity = random.between(d.spinMin, d.spinMax) * random.direction();
  return def;
}

std::size_t World::addSpawner(const SpawnerDef& def) {
  const std::string problem = checkSpawner(def);
  if (!problem.empty()) throw std::invalid_argument("spawner '" + def.name + "': " + problem);
  static_cast<void>(RigidBody(def.prototype));  // the prototype's own checks, now rather than at its first burst
  Spawner spawner;
  spawner.def = def;
  spawner.random = UniformRandom(def.seed);
  // A spawner added late starts with its next burst, not with all those it missed.
  if (def.start < time()) spawner.bursts = static_cast<std::uint64_t>(std::ceil((time() - def.start) / def.period));
  spawners_.push_back(std::move(spawner));
  return spawners_.size() - 1;
}

void World::setKillVolume(const Aabb& volume) {
  if (volume.min.hasNaN() || volume.max.hasNaN()) throw std::invalid_argument("kill volume: a corner is not a number");
  killVolume_ = volume;
}

void World::spawnAndRemove() {
  if (!killVolume_.empty()) {
    // From the last body down: destroying one moves the last into its index, which is then past i.
    for (std::size_t i = bodies_.size(); i-- > 0;) {
      const Vec3& x = bodies_[i].position();
      if ((x.array() >= killVolume_.min.array()).all() && (x.array() <= killVolume_.max.array()).all()) continue;
      const BodyId id = idAt(i);
      destroyBody(id);
      removedNow_.push_back(id);
    }
  }
  const double t = time();
  // Half a step early: a burst due at 1.0 s happens at the step starting then, not one later for
  // the rounding of 60 x (1/60).
  const double due = t + 0.5 * settings_.timeStep;
  for (Spawner& spawner : spawners_) {
    while (spawner.nextTime() <= due && spawner.nextTime() < spawner.def.end) {
      for (int k = 0; k < spawner.def.count; ++k) spawnedNow_.push_back(addBody(drawSpawn(spawner)));
      ++spawner.bursts;
    }
  }
}

}  // namespace rbsim
