#include "rbsim/world/systems.h"
#include "rbsim/scene/scene.h"

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "rbsim/io/input_error.h"
#include "io/obj_loader.h"
#include "io/read_file.h"
#include "rbsim/mass/mass_model.h"
#include "scene/body_parser.h"
#include "scene/scene_cache.h"
#include "scene/input_ranges.h"
#include "scene/joint_parser.h"
#include "rbsim/scene/json_fields.h"
#include "scene/particle_parser.h"
#include "scene/ragdoll_parser.h"
#include "scene/scene_file_keys.h"
#include "scene/planar_parser.h"
#include "rbsim/scene/scene_parts.h"
#include "rbsim/world/made_names.h"
#include "scene/sdf_slice_parser.h"
#include "scene/soft_parser.h"
#include "rbsim/scene/strict_json.h"

namespace rbsim {

namespace {

// A scene is a page of JSON: 64 MiB holds hundreds of thousands of bodies' keys. Checked before
// reading (io/read_file.h), so /dev/zero or a file of gigabytes ends in a message, not in bad_alloc.
constexpr std::uintmax_t kMaxSceneBytes = std::uintmax_t{64} << 20;  // [bytes]
// A run's work is bounded as well as its step count: a 1000-box pile costs about 10 us per body
// and step with soft step (REPORT.md section 5, 9.6 ms a step), so 1e10 body-steps is about a
// day of computing, beyond what anyone waits for without meaning to.
constexpr double kMaxBodySteps = 1e10;      // [bodies x steps]
constexpr double kSecondsPerBodyStep = 1e-5;  // [s], the pile's measured cost, for the estimate

void parseView(const JsonObject& root, Scene& scene) {
  if (!root.has("view")) return;
  const JsonObject v = root.object("view", kViewKeys);
  parseViewFields(v, scene.view);
  if (v.has("selected")) scene.view.selected = scene_detail::findBody(scene.bodies, v, "selected");
  if (v.has("sdf_slice")) scene.view.sdfSlice = parseSdfSlice(v.object("sdf_slice", kSdfSliceKeys), scene);
}

void checkWorkBudget(const JsonObject& root, const Scene& scene) {
  // Every body the scene makes, counted at the most it holds at once: a bound on each step's.
  const double bodies = scene.mostBodiesAtOnce();
  const double work = bodies * static_cast<double>(scene.stepCount());
  if (work <= kMaxBodySteps) return;
  std::ostringstream problem;
  problem << bodies << " bodies x " << scene.stepCount() << " steps = " << work
          << " body-steps, about " << work * kSecondsPerBodyStep / 3600.0 << " hours at the "
          << kSecondsPerBodyStep * 1e6 << " us a body-step a pile of boxes costs; the limit is " << kMaxBodySteps
          << " (about a day): expected fewer steps or bodies";
  const bool bySteps = root.has("world") && root.raw("world").contains("steps");
  throw InputError(root.file(), bySteps ? "world.steps" : "world.duration", problem.str());
}

// No body, listed or made at load (a ragdoll's bones), has a name a periodic spawner will make
// while the World steps (issue 56, item 4): two bodies would share it.
void checkSpawnedNames(const std::string& file, const std::vector<JsonObject>& bodies, const Scene& scene) {
  if (scene.spawners.empty()) return;
  const auto check = [&](const std::string& name, const JsonObject* listed) {
    for (const SpawnerDef& spawner : scene.spawners) {
      if (!spawnerMakesName(spawner, name)) continue;
      if (listed != nullptr) listed->fail("name", madeNameProblem(spawner, name));
      throw InputError(file, "spawn", madeNameProblem(spawner, name));  // a ragdoll spawned at load
    }
  };
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) check(scene.bodies[i].name, i < bodies.size() ? &bodies[i] : nullptr);
  for (const RagdollDef& ragdoll : scene.ragdolls) {  // the listed ones were checked by parseRagdolls
    for (const std::string& bone : ragdollBodyNames(ragdoll.name)) check(bone, nullptr);
  }
}

}  // namespace

std::uint64_t Scene::stepCount() const {
  return static_cast<std::uint64_t>(std::llround(duration / settings.timeStep));
}

Scene parseScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir) {
  SceneCache cache;
  Scene scene = describeScene(document, file, baseDir, &cache);
  cookScene(scene, &cache);
  return scene;
}

Scene describeScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir,
                    SceneCache* cache) {
  const JsonObject root(document, file, "", scene_detail::kSceneKeys);
  Scene scene;
  scene.file = file;
  scene.title = root.string("title", std::filesystem::path(file).stem().string());
  if (root.has("world")) parseWorldBlock(root.object("world", kWorldKeys), scene);
  const std::vector<JsonObject> bodies = root.objectArray("bodies", scene_detail::kBodyKeys);
  scene_detail::ShapeCache ownShapes;  // bodies of one shape share it (issue 34)
  scene_detail::ShapeCache& shapes = cache != nullptr ? cache->impl().shapes : ownShapes;
  shapes.beginScene();
  for (const JsonObject& b : bodies) {
    if (const std::optional<Vec3> color = scene_detail::parseBody(b, baseDir, scene, &shapes)) {
      scene.colors.byBody[scene.bodies.back().name] = *color;
    }
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) scene_detail::parseScripts(bodies[i], i, scene);
  scene_detail::parseSpawns(root, baseDir, scene, &shapes);
  const auto nonEmpty = [&](const char* key) { return root.has(key) && root.raw(key).is_array() && !root.raw(key).empty(); };
  if (root.has("kill_volume")) {
    const JsonObject k = root.object("kill_volume", scene_detail::kRegionKeys);
    scene.killVolume.min = k.boundedVec3("min", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
    scene.killVolume.max = k.boundedVec3("max", Vec3::Zero(), kMaxCoordinate, "m", kFarFromOrigin);
    if (!(scene.killVolume.min.array() < scene.killVolume.max.array()).all()) k.fail("max", "expected every component > min's");
  }
  scene_detail::parseRagdolls(root, scene);
  if (scene.bodies.empty() && scene.spawners.empty() && scene.ragdolls.empty() && !nonEmpty("particles") && !nonEmpty("soft_bodies") && !root.has("planar")) {
    throw InputError(file, "bodies", "expected a non-empty array of bodies (or a spawn block, particles, soft bodies or a planar world)");
  }
  std::unordered_map<std::string, std::size_t> names;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (!names.emplace(scene.bodies[i].name, i).second) {
      const std::string problem = "duplicate body name \"" + scene.bodies[i].name + "\"";
      if (i < bodies.size()) bodies[i].fail("name", problem);
      throw InputError(file, "spawn", problem + " (spawned names are NAME_k)");
    }
  }
  checkSpawnedNames(file, bodies, scene);
  checkWorkBudget(root, scene);
  scene_detail::parsePlanes(root, scene);
  scene_detail::parseJoints(root, scene);
  scene_detail::parseParticleSystems(root, scene);
  scene_detail::parseSoftBodies(root, scene);
  scene_detail::parsePlanar(root, scene);
  parseView(root, scene);
  return scene;
}

std::string readSceneFile(const std::string& path) {
  return readTextFile(path, kMaxSceneBytes, "", "a scene file (JSON)");
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  return parseSceneText(readSceneFile(path), path, std::filesystem::path(path).parent_path().string(), overrides);
}

nlohmann::json readSceneDocument(const std::string& text, const std::string& file,
                                 const std::vector<std::string>& overrides) {
  nlohmann::json document = parseStrictJson(text, file);  // syntax, duplicate keys, depth
  for (const std::string& assignment : overrides) {
    try {
      applyOverride(document, assignment);
    } catch (const InputError& e) {
      throw InputError(file, "--set " + assignment, e.problem());
    }
  }
  return document;
}

Scene parseSceneText(const std::string& text, const std::string& file, const std::string& baseDir,
                     const std::vector<std::string>& overrides) {
  return parseScene(readSceneDocument(text, file, overrides), file, baseDir);
}

World buildWorld(const Scene& scene) {
  if (!scene.cooking.empty()) throw std::logic_error("buildWorld: the scene is not cooked; call cookScene first");
  World world(scene.settings);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (world.addBody(scene.bodies[i]) != sceneBodyId(i)) throw std::logic_error("buildWorld: a fresh World numbered its bodies out of order");
  }
  for (const ScriptedForce& f : scene.forces) world.addForce(f);
  for (const PoseEvent& e : scene.poseEvents) world.addPoseEvent(e);
  for (const KinematicMotion& m : scene.motions) setKinematicMotion(world, m);
  for (const SpawnerDef& s : scene.spawners) addSpawner(world, s);
  if (!scene.killVolume.empty()) setKillVolume(world, scene.killVolume);
  for (const Spring& s : scene.springs) addSpring(world, s);
  for (const JointDef& j : scene.joints) world.addJoint(j);
  for (const RagdollDef& r : scene.ragdolls) addRagdoll(world, r);
  for (std::size_t p = 0; p < scene.planes.size(); ++p) world.addPlane(scene.planes[p], scene.planeMaterials[p]);
  for (const ParticleSystemDef& def : scene.particleSystems) addParticleSystem(world, def);
  for (const SoftBodyDef& def : scene.softBodies) addSoftBody(world, def);
  if (scene.planar) setPlanarWorld(world, *scene.planar);
  return world;
}

}  // namespace rbsim
