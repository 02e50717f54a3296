#include "rbsim/scene/scene.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "rbsim/io/input_error.h"
#include "rbsim/io/obj_loader.h"
#include "rbsim/io/read_file.h"
#include "rbsim/mass/mass_model.h"
#include "rbsim/scene/body_parser.h"
#include "rbsim/scene/input_ranges.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/particle_parser.h"
#include "rbsim/scene/planar_parser.h"
#include "rbsim/scene/soft_parser.h"
#include "rbsim/scene/strict_json.h"

namespace rbsim {

namespace {

// Beyond this a video shows nothing a person can see, and it is most likely a typo.
constexpr int kMaxFramesPerSecond = 240;  // [1/s]
// A scene is a page of JSON: 64 MiB holds hundreds of thousands of bodies' keys. Checked before
// reading (io/read_file.h), so /dev/zero or a file of gigabytes ends in a message, not in bad_alloc.
constexpr std::uintmax_t kMaxSceneBytes = std::uintmax_t{64} << 20;  // [bytes]
// A run's work is bounded as well as its step count: a 1000-box pile costs about 10 us per body
// and step with soft step (REPORT.md section 5, 9.6 ms a step), so 1e10 body-steps is about a
// day of computing, beyond what anyone waits for without meaning to.
constexpr double kMaxBodySteps = 1e10;      // [bodies x steps]
constexpr double kSecondsPerBodyStep = 1e-5;  // [s], the pile's measured cost, for the estimate
// world.steps accepts at most 1e9 (json_fields' positiveInt); a duration may not ask for more.
constexpr double kMaxSteps = 1e9;

void parseView(const JsonObject& root, Scene& scene) {
  if (!root.has("view")) return;
  const JsonObject v = root.object("view", {"camera", "size", "fps", "overlay", "wireframe", "axes", "grid", "aabbs", "contacts", "selected", "caption"});
  ViewDesc& view = scene.view;
  if (v.has("camera")) {
    const JsonObject c = v.object("camera", {"eye", "target", "up", "fov_deg"});
    view.eye = c.vec3("eye", view.eye);
    view.target = c.vec3("target", view.target);
    view.up = c.vec3("up", view.up);
    view.fovDegrees = c.positiveNumber("fov_deg", view.fovDegrees);
    if (view.fovDegrees >= 180.0) c.fail("fov_deg", "expected an angle below 180 degrees");
    if ((view.eye - view.target).norm() == 0.0) c.fail("target", "must differ from \"eye\"");
    if ((view.eye - view.target).cross(view.up).norm() == 0.0) c.fail("up", "must not be parallel to the view direction");
  }
  if (v.has("size")) {
    const nlohmann::json& s = v.raw("size");
    if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer() ||
        s[0].get<long long>() < 16 || s[1].get<long long>() < 16 || s[0].get<long long>() > 8192 ||
        s[1].get<long long>() > 8192) {
      v.fail("size", "expected [width, height] in pixels, each an integer in [16, 8192]");
    }
    view.width = s[0].get<int>();
    view.height = s[1].get<int>();
    if (view.width % 2 != 0 || view.height % 2 != 0) v.fail("size", "H.264 in yuv420p needs even width and height");
  }
  view.fps = v.positiveInt("fps", view.fps);
  if (view.fps > kMaxFramesPerSecond) v.fail("fps", "expected at most " + std::to_string(kMaxFramesPerSecond) + " frames per second");
  view.overlay = v.boolean("overlay", view.overlay);
  view.wireframe = v.boolean("wireframe", view.wireframe);
  view.axes = v.boolean("axes", view.axes);
  view.grid = v.boolean("grid", view.grid);
  view.aabbs = v.boolean("aabbs", view.aabbs);
  view.contacts = v.boolean("contacts", view.contacts);
  view.caption = v.string("caption", view.caption);
  if (v.has("selected")) view.selected = scene_detail::findBody(scene.bodies, v, "selected");
}

void checkWorkBudget(const JsonObject& root, const Scene& scene) {
  const double work = static_cast<double>(scene.bodies.size()) * static_cast<double>(scene.stepCount());
  if (work <= kMaxBodySteps) return;
  std::ostringstream problem;
  problem << scene.bodies.size() << " bodies x " << scene.stepCount() << " steps = " << work
          << " body-steps, about " << work * kSecondsPerBodyStep / 3600.0 << " hours at the "
          << kSecondsPerBodyStep * 1e6 << " us a body-step a pile of boxes costs; the limit is " << kMaxBodySteps
          << " (about a day): expected fewer steps or bodies";
  const bool bySteps = root.has("world") && root.raw("world").contains("steps");
  throw InputError(root.file(), bySteps ? "world.steps" : "world.duration", problem.str());
}

}  // namespace

std::uint64_t Scene::stepCount() const {
  return static_cast<std::uint64_t>(std::llround(duration / settings.timeStep));
}

Scene parseScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir) {
  const JsonObject root(document, file, "", {"title", "world", "view", "bodies", "planes", "spawn", "particles", "soft_bodies", "planar"});
  Scene scene;
  scene.file = file;
  scene.title = root.string("title", std::filesystem::path(file).stem().string());
  if (root.has("world")) {
    const JsonObject w = root.object("world", {"gravity", "dt", "integrator", "inertia", "duration", "steps", "sleep",
                                               "sleep_linear_speed", "sleep_angular_speed", "time_to_sleep",
                                               "collisions", "ccd", "ccd_motion_fraction", "broad_phase",
                                               "contact_margin", "solver", "substeps", "contact_hertz",
                                               "contact_damping_ratio", "contact_push_speed", "velocity_iterations",
                                               "position_iterations", "restitution_threshold", "contact_slop",
                                               "position_correction", "warm_starting", "warm_start_distance",
                                               "response", "log_queries", "query_log_capacity", "skip_idle_stages",
                                               "particle_integrator"});
    // Every Settings field, read as the type it is; the ranges are checkSettings's alone.
    Settings& s = scene.settings;
    s.gravity = w.vec3("gravity", s.gravity);
    s.timeStep = w.number("dt", s.timeStep);
    s.allowSleep = w.boolean("sleep", s.allowSleep);
    s.sleepLinearSpeed = w.number("sleep_linear_speed", s.sleepLinearSpeed);
    s.sleepAngularSpeed = w.number("sleep_angular_speed", s.sleepAngularSpeed);
    s.timeToSleep = w.number("time_to_sleep", s.timeToSleep);
    s.detectCollisions = w.boolean("collisions", s.detectCollisions);
    s.continuousCollision = w.boolean("ccd", s.continuousCollision);
    s.ccdMotionFraction = w.number("ccd_motion_fraction", s.ccdMotionFraction);
    const std::string broad = w.string("broad_phase", "sap");
    if (broad == "brute-force") {
      s.broadPhase = Settings::BroadPhaseMethod::BruteForce;
    } else if (broad != "sap") {
      w.fail("broad_phase", "expected \"sap\" or \"brute-force\", got \"" + broad + "\"");
    }
    s.contactMargin = w.number("contact_margin", s.contactMargin);
    const std::string solver = w.string("solver", "soft-step");
    if (solver == "pgs") {
      s.solver = Settings::ContactSolverMethod::Pgs;
    } else if (solver != "soft-step") {
      w.fail("solver", "expected \"soft-step\" or \"pgs\", got \"" + solver + "\"");
    }
    const auto integer = [&](const char* key, int fallback) {
      if (!w.has(key)) return fallback;
      const double x = w.number(key, fallback);
      if (x != std::floor(x) || std::abs(x) > 1e9) w.fail(key, "expected an integer");
      return static_cast<int>(x);
    };
    s.substeps = integer("substeps", s.substeps);
    s.contactHertz = w.number("contact_hertz", s.contactHertz);
    s.contactDampingRatio = w.number("contact_damping_ratio", s.contactDampingRatio);
    s.contactPushSpeed = w.number("contact_push_speed", s.contactPushSpeed);
    s.velocityIterations = integer("velocity_iterations", s.velocityIterations);
    s.positionIterations = integer("position_iterations", s.positionIterations);
    s.restitutionThreshold = w.number("restitution_threshold", s.restitutionThreshold);
    s.contactSlop = w.number("contact_slop", s.contactSlop);
    s.positionCorrection = w.number("position_correction", s.positionCorrection);
    s.warmStarting = w.boolean("warm_starting", s.warmStarting);
    s.warmStartDistance = w.number("warm_start_distance", s.warmStartDistance);
    s.respondToContacts = w.boolean("response", s.respondToContacts);
    s.logQueries = w.boolean("log_queries", s.logQueries);
    const int capacity = integer("query_log_capacity", static_cast<int>(s.queryLogCapacity));
    s.queryLogCapacity = capacity < 1 ? 0 : static_cast<std::size_t>(capacity);
    s.skipIdleStages = w.boolean("skip_idle_stages", s.skipIdleStages);
    if (const SettingsProblem problem = checkSettings(s)) w.fail(problem.key.c_str(), problem.expectation);
    const std::string integrator = w.string("integrator", integratorName(scene.settings.integrator));
    if (!parseIntegrator(integrator, scene.settings.integrator)) {
      std::string names;
      for (const std::string& n : integratorNames()) names += (names.empty() ? "" : ", ") + n;
      const std::string near = nearestKey(integrator, integratorNames());
      const std::string hint = near.empty() ? "" : " (did you mean \"" + near + "\"?)";
      w.fail("integrator", "unknown integrator \"" + integrator + "\"" + hint + "; expected one of " + names);
    }
    const std::string particles = w.string("particle_integrator", particleIntegratorName(scene.particleIntegrator));
    if (!parseParticleIntegrator(particles, scene.particleIntegrator)) {
      w.fail("particle_integrator", "unknown particle integrator \"" + particles + "\"; expected explicit-euler or semi-implicit-euler");
    }
    const std::string inertia = w.string("inertia", inertiaMethodName(scene.settings.inertia));
    if (!parseInertiaMethod(inertia, scene.settings.inertia)) w.fail("inertia", "expected \"cube\" or \"exact\"");
    scene.duration = w.positiveNumber("duration", scene.duration);
    if (scene.duration / scene.settings.timeStep > kMaxSteps) {
      std::ostringstream expected;
      expected << "a duration of " << scene.duration << " s at dt = " << scene.settings.timeStep << " s is "
               << scene.duration / scene.settings.timeStep << " steps; expected at most " << kMaxSteps;
      w.fail("duration", expected.str());
    }
    if (w.has("steps")) scene.duration = w.positiveInt("steps", 1) * scene.settings.timeStep;
    if (scene.stepCount() == 0) {
      std::ostringstream expected;
      expected << "a duration of " << scene.duration << " s is less than half a time step (dt = "
               << scene.settings.timeStep << " s): it would run no step; expected at least " << scene.settings.timeStep
               << " s";
      w.fail("duration", expected.str());
    }
  }
  const std::vector<JsonObject> bodies = root.objectArray("bodies", scene_detail::kBodyKeys);
  for (const JsonObject& b : bodies) scene_detail::parseBody(b, baseDir, scene);
  for (std::size_t i = 0; i < bodies.size(); ++i) scene_detail::parseScripts(bodies[i], i, scene);
  scene_detail::parseSpawns(root, baseDir, scene);
  const auto nonEmpty = [&](const char* key) { return root.has(key) && root.raw(key).is_array() && !root.raw(key).empty(); };
  if (scene.bodies.empty() && !nonEmpty("particles") && !nonEmpty("soft_bodies") && !root.has("planar")) {
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
  checkWorkBudget(root, scene);
  scene_detail::parsePlanes(root, scene);
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

Scene parseSceneText(const std::string& text, const std::string& file, const std::string& baseDir,
                     const std::vector<std::string>& overrides) {
  nlohmann::json document = parseStrictJson(text, file);
  for (const std::string& assignment : overrides) {
    try {
      applyOverride(document, assignment);
    } catch (const InputError& e) {
      throw InputError(file, "--set " + assignment, e.problem());
    }
  }
  return parseScene(document, file, baseDir);
}

World buildWorld(const Scene& scene) {
  World world(scene.settings);
  for (const BodyDef& def : scene.bodies) world.addBody(def);
  for (const ScriptedForce& f : scene.forces) world.addForce(f);
  for (const PoseEvent& e : scene.poseEvents) world.addPoseEvent(e);
  for (const Spring& s : scene.springs) world.addSpring(s);
  for (std::size_t p = 0; p < scene.planes.size(); ++p) world.addPlane(scene.planes[p], scene.planeMaterials[p]);
  for (const ParticleSystemDef& def : scene.particleSystems) world.addParticleSystem(def);
  for (const SoftBodyDef& def : scene.softBodies) world.addSoftBody(def);
  if (scene.planar) world.setPlanarWorld(*scene.planar);
  return world;
}

}  // namespace rbsim
