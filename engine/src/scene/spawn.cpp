// "spawn" blocks: many bodies from one template, with positions, velocities and orientations
// drawn from a seeded generator so that a scene file describes a reproducible crowd.
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <string>

#include "rbsim/math/uniform_random.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/world/made_names.h"
#include "rbsim/world/spawner.h"
#include "scene/body_parser.h"
#include "scene/input_ranges.h"
#include "scene/ragdoll_parser.h"

namespace rbsim::scene_detail {

namespace {

// Vertices of all spawned bodies together: each body keeps its world-frame vertices (24 B each)
// and its collision shape, so this is ~0.5 GB of per-body geometry; the template's mesh is shared.
constexpr double kMaxSpawnedVertices = 2e7;  // [vertices]

// [lo, hi] with 0 <= lo <= hi.
std::pair<double, double> range(const JsonObject& o, const char* key, const char* unit) {
  if (!o.has(key)) return {0.0, 0.0};
  const nlohmann::json& r = o.raw(key);
  if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() || !(r[0].get<double>() >= 0.0) ||
      !(r[1].get<double>() >= r[0].get<double>()) || !std::isfinite(r[1].get<double>())) {
    o.fail(key, std::string("expected [low, high] with 0 <= low <= high, in ") + unit);
  }
  return {r[0].get<double>(), r[1].get<double>()};
}

// "offsets": [[x, y, z], ...], each within the scene's coordinates; [[0, 0, 0]] when left out.
std::vector<Vec3> offsetsOf(const JsonObject& s) {
  if (!s.has("offsets")) return {Vec3::Zero()};
  const nlohmann::json& list = s.raw("offsets");
  const std::string expected = "expected a non-empty array of at most " + std::to_string(kMaxSpawnCount) +
                               " offsets [x, y, z] from each drawn point, each within " + formatNumber(kMaxCoordinate) + " m";
  if (!list.is_array() || list.empty() || list.size() > static_cast<std::size_t>(kMaxSpawnCount)) s.fail("offsets", expected);
  std::vector<Vec3> offsets;
  for (const nlohmann::json& p : list) {
    if (!p.is_array() || p.size() != 3) s.fail("offsets", expected);
    Vec3 offset;
    for (int k = 0; k < 3; ++k) {
      if (!p[k].is_number() || !(std::abs(p[k].get<double>()) <= kMaxCoordinate)) s.fail("offsets", expected);
      offset[k] = p[k].get<double>();
    }
    offsets.push_back(offset);
  }
  return offsets;
}

// A spawner's state before its first burst: a load-time block draws as that burst would.
Spawner firstBurst(const SpawnerDef& def) {
  Spawner draws;
  draws.def = def;
  draws.random = UniformRandom(def.seed);
  return draws;
}

void spawnRagdolls(const JsonObject& s, bool periodic, double bursts, SpawnerDef& spawner, Scene& scene, double& spawnedVertices);
void spawnBodies(const JsonObject& s, const std::string& baseDir, bool periodic, double bursts, SpawnerDef& spawner,
                 Scene& scene, ShapeCache* shapes, double& spawnedVertices);

}  // namespace

void parseSpawns(const JsonObject& root, const std::string& baseDir, Scene& scene, ShapeCache* shapes) {
  double spawnedVertices = 0.0;  // over every block so far
  const std::vector<JsonObject> blocks = root.objectArray("spawn", kSpawnKeys);
  // Each block's name, given or the first default no block gives: two blocks of one name would
  // name their bodies alike (issue 56, item 4).
  std::set<std::string> names;
  for (const JsonObject& s : blocks) {
    if (s.has("name")) names.insert(s.string("name", ""));
  }
  std::set<std::string> used;
  for (const JsonObject& s : blocks) {
    const std::string name =
        s.has("name") ? s.string("name", "") : freeSpawnerName([&](const std::string& n) { return names.count(n) != 0 || used.count(n) != 0; });
    if (!used.insert(name).second) {
      s.fail("name", "another spawn block is named \"" + name + "\"; expected a name of its own (its bodies are named NAME_k)");
    }
    parseSpawn(s, baseDir, scene, shapes, spawnedVertices, name);
  }
}

void parseSpawn(const JsonObject& s, const std::string& baseDir, Scene& scene, ShapeCache* shapes, double& spawnedVertices,
                const std::string& defaultName) {
  {
    const int count = s.positiveInt("count", 1);
    if (count > kMaxSpawnCount) s.fail("count", "expected at most " + std::to_string(kMaxSpawnCount) + " bodies per block");
    // With a period the block spawns `count` points' copies at start, start + period, ... while the World
    // steps (world/spawner.h); without, all of them at load.
    const bool periodic = s.has("period");
    const double period = periodic ? s.positiveNumber("period", 1.0) : 0.0;
    if (periodic) {
      const std::string tooShort = checkSpawnPeriod(period, scene.settings.timeStep);
      if (!tooShort.empty()) s.fail("period", tooShort.substr(tooShort.find(": ") + 2));
    }
    const double start = s.number("start", 0.0);
    if (!(start >= 0.0)) s.fail("start", "expected a time >= 0 s");
    const double end = s.number("end", std::numeric_limits<double>::infinity());
    if (!(end > start)) s.fail("end", "expected a time after start");
    if (!periodic && (s.has("start") || s.has("end"))) s.fail(s.has("start") ? "start" : "end", "only a block with a \"period\" spawns over time");
    const std::vector<Vec3> offsets = offsetsOf(s);
    // Copies per burst: one per drawn point and offset, eleven bodies per ragdoll.
    const bool ragdoll = s.has("ragdoll");
    if (ragdoll == s.has("body")) s.fail("body", "expected either a \"body\" or a \"ragdoll\" to copy");
    const double bodiesPerBurst = static_cast<double>(count) * static_cast<double>(offsets.size()) *
                                  (ragdoll ? static_cast<double>(kBoneCount) : 1.0);
    if (bodiesPerBurst > kMaxSpawnCount) {
      s.fail("offsets", formatNumber(bodiesPerBurst) + " bodies a burst (count x offsets" + (ragdoll ? " x 11 bones" : "") +
                            "); expected at most " + std::to_string(kMaxSpawnCount));
    }
    const double lifetime = s.has("lifetime") ? s.positiveNumber("lifetime", 1.0) : std::numeric_limits<double>::infinity();
    if (!periodic && s.has("lifetime")) s.fail("lifetime", "only a block with a \"period\" removes what it spawned");
    // Bursts within the run: what the block adds in all, held to the same budget as one at load.
    const double span = std::min(end, scene.duration) - start;
    // (A World stepped without end, from Python, holds each burst to it.)
    const double bursts = !periodic || !std::isfinite(span) ? 1.0 : span > 0.0 ? std::ceil(span / period) : 0.0;
    if (bodiesPerBurst * bursts > kMaxSpawnCount) {
      s.fail("period", formatNumber(bodiesPerBurst) + " bodies every " + formatNumber(period) + " s for " + formatNumber(span) +
                           " s add " + formatNumber(bodiesPerBurst * bursts) + " bodies; expected at most " +
                           std::to_string(kMaxSpawnCount) + " (a longer period, fewer bodies, or an end)");
    }
    // The bursts alive at once, whose vertices are held at once: a lifetime removes the older ones.
    const double aliveBursts = burstsAliveAtOnce(bursts, lifetime, period);
    const int seed = s.has("seed") ? s.positiveInt("seed", 1) : 1;
    const std::string prefix = s.string("name", defaultName);
    const JsonObject region = s.object("region", kRegionKeys);
    const Vec3 lo = region.boundedVec3("min", Vec3::Zero(), kMaxCoordinate, "m", "the farthest a body may start"),
               hi = region.boundedVec3("max", Vec3::Zero(), kMaxCoordinate, "m", "the farthest a body may start");
    if ((hi.array() < lo.array()).any()) region.fail("max", "expected every component >= min's");
    // Positions are drawn as min + (max - min) u: the extent itself must be a finite number.
    const Vec3 extent = hi - lo;
    if (!extent.allFinite()) {
      region.fail("max", "the region's extent max - min overflows (" + formatNumber(extent.maxCoeff()) +
                             " m); expected a finite size along every axis");
    }
    // A copy starts at a drawn point plus its offset: the sum, not each part, is held to 1e6 m
    // (issue 56, item 5: a region and an offset each at 1e6 m put bodies at 2e6 m).
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      const double far = (lo + offsets[i]).cwiseAbs().cwiseMax((hi + offsets[i]).cwiseAbs()).stableNorm();
      if (!(far <= kMaxCoordinate)) {
        s.fail("offsets", "offsets[" + std::to_string(i) + "] puts copies up to " + formatNumber(far) +
                              " m from the origin (the region's corner plus the offset); expected at most " +
                              formatNumber(kMaxCoordinate) + " m (" + kFarFromOrigin + ")");
      }
    }
    const auto [speedLo, speedHi] = range(s, "speed", "m/s");
    if (speedHi > kMaxSpeed) s.fail("speed", "expected speeds below the speed of light, 299792458 m/s");
    const auto [spinLo, spinHi] = range(s, "angular_speed", "rad/s");
    const bool randomOrientation = s.boolean("random_orientation", true);

    SpawnerDef spawner;
    spawner.name = prefix;
    spawner.count = count;
    spawner.offsets = offsets;
    spawner.lifetime = lifetime;
    spawner.start = start;
    spawner.period = periodic ? period : 1.0;
    spawner.end = end;
    spawner.regionMin = lo;
    spawner.regionMax = hi;
    spawner.speedMin = speedLo;
    spawner.speedMax = speedHi;
    spawner.spinMin = spinLo;
    spawner.spinMax = spinHi;
    spawner.randomOrientation = randomOrientation;
    spawner.seed = static_cast<std::uint64_t>(seed);
    if (ragdoll) {
      spawnRagdolls(s, periodic, aliveBursts, spawner, scene, spawnedVertices);
    } else {
      spawnBodies(s, baseDir, periodic, aliveBursts, spawner, scene, shapes, spawnedVertices);
    }
  }
}

namespace {

// Every spawned body keeps its own world-frame copy of its mesh: `copies` of `vertices` each join
// the budget of every block so far.
void addSpawnedVertices(const JsonObject& s, double copies, std::size_t vertices, const char* what, double& spawnedVertices) {
  spawnedVertices += copies * static_cast<double>(vertices);
  if (spawnedVertices > kMaxSpawnedVertices) {
    s.fail("count", formatNumber(copies) + " " + what + " of " + std::to_string(vertices) +
                        " vertices bring the spawned bodies to " + formatNumber(spawnedVertices) +
                        " vertices (each body keeps its own world-frame copy); the limit is " +
                        formatNumber(kMaxSpawnedVertices) + " vertices: spawn fewer bodies or a coarser mesh");
  }
}

void spawnRagdolls(const JsonObject& s, bool periodic, double bursts, SpawnerDef& spawner, Scene& scene, double& spawnedVertices) {
  if (scene.settings.solver != Settings::ContactSolverMethod::SoftStep) {
    s.fail("ragdoll", "a ragdoll's joints need the soft-step solver; expected world.solver \"soft-step\"");
  }
  if (spawner.spinMax > 0.0) s.fail("angular_speed", "a ragdoll is spawned without spin; expected none");
  RagdollDef figure;
  parseRagdollFigure(s.object("ragdoll", kRagdollFigureKeys), figure);
  spawner.ragdoll = figure;
  // The bones count with the bodies (issue 56, item 1: they were skipped).
  const double figures = static_cast<double>(spawner.count) * static_cast<double>(spawner.offsets.size()) * bursts;
  addSpawnedVertices(s, figures, ragdollVertexCount(), "figures", spawnedVertices);
  if (periodic) {
    scene.spawners.push_back(spawner);
    return;
  }
  // At load, the same draws a spawner's first burst makes.
  Spawner draws = firstBurst(spawner);
  for (int k = 0; k < spawner.count; ++k) {
    const SpawnDraw draw = drawPoint(draws);
    for (const Vec3& offset : spawner.offsets) scene.ragdolls.push_back(spawnRagdoll(draws, draw, offset));
  }
}

void spawnBodies(const JsonObject& s, const std::string& baseDir, bool periodic, double bursts, SpawnerDef& spawner,
                 Scene& scene, ShapeCache* shapes, double& spawnedVertices) {
  // The template is parsed once (errors name spawn[i].body...), then copied: the mesh is shared.
  const JsonObject body = s.object("body", kSpawnBodyKeys);
  const std::size_t first = scene.bodies.size();
  const std::size_t springsBefore = scene.springs.size();
  const std::optional<Vec3> color = parseBody(body, baseDir, scene, shapes);
  if (color) scene.colors.bySpawner[spawner.name] = *color;
  parseScripts(body, first, scene);
  const BodyDef prototype = scene.bodies[first];
  const double copies = static_cast<double>(spawner.count) * static_cast<double>(spawner.offsets.size()) * bursts;
  addSpawnedVertices(s, copies, prototype.mesh->vertices.size(), "bodies", spawnedVertices);
  // The fastest spin a draw can give keeps the surface below light speed, as for a body's own
  // angular_velocity; with the template's mass within kMaxMassScale, m v and I omega stay finite.
  const double radius = 0.5 * (prototype.mesh->boundsMax() - prototype.mesh->boundsMin()).norm();
  if (!(spawner.spinMax * radius <= kMaxSpeed)) {
    s.fail("angular_speed", "a body's surface would move at |omega| r = " + formatNumber(spawner.spinMax) + " rad/s x " +
                                formatNumber(radius) + " m, faster than light; expected a smaller spin");
  }
  const std::string inertia = scene.inertiaMethods[first];
  const std::size_t springsOfPrototype = scene.springs.size();
  scene.bodies.pop_back();
  scene.inertiaMethods.pop_back();
  spawner.prototype = prototype;
  if (periodic) {
    if (scene.springs.size() > springsBefore) s.fail("body", "a body spawned over time cannot have springs");
    scene.spawners.push_back(spawner);
    return;
  }
  // At load, the same draws a spawner's first burst makes; the prototype's springs (which name the
  // first copy) are copied to every other.
  Spawner draws = firstBurst(spawner);
  for (int k = 0; k < spawner.count; ++k) {
    const SpawnDraw draw = drawPoint(draws);
    for (const Vec3& offset : spawner.offsets) {
      const std::size_t index = scene.bodies.size();
      scene.bodies.push_back(spawnBody(draws, draw, offset));
      scene.inertiaMethods.push_back(inertia);
      if (index == first) continue;
      for (std::size_t i = 0; i < springsOfPrototype; ++i) {
        if (scene.springs[i].body != sceneBodyId(first)) continue;
        Spring copy = scene.springs[i];
        copy.body = sceneBodyId(index);
        scene.springs.push_back(copy);
      }
    }
  }
}

}  // namespace

}  // namespace rbsim::scene_detail
