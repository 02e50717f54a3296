#include "rbsim/scene/scene_parts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rbsim/io/input_error.h"
#include "scene/body_parser.h"
#include "scene/input_ranges.h"
#include "scene/joint_parser.h"

namespace rbsim {

namespace {

// world.steps accepts at most 1e9 (json_fields' positiveInt); a duration may not ask for more.
constexpr double kMaxSteps = 1e9;

}  // namespace

void parseWorldSettings(const JsonObject& w, Settings& s) {
  // Every Settings field, read as the type it is; the ranges are checkSettings's alone.
  s.gravity = w.vec3("gravity", s.gravity);
  s.timeStep = w.number("dt", s.timeStep);
  s.allowSleep = w.boolean("sleep", s.allowSleep);
  s.driftCorrection = w.boolean("drift_correction", s.driftCorrection);
  s.sleepLinearSpeed = w.number("sleep_linear_speed", s.sleepLinearSpeed);
  s.sleepAngularSpeed = w.number("sleep_angular_speed", s.sleepAngularSpeed);
  s.timeToSleep = w.number("time_to_sleep", s.timeToSleep);
  s.detectCollisions = w.boolean("collisions", s.detectCollisions);
  s.continuousCollision = w.boolean("ccd", s.continuousCollision);
  s.ccdMotionFraction = w.number("ccd_motion_fraction", s.ccdMotionFraction);
  const std::string broad = w.string("broad_phase", broadPhaseName(s.broadPhase));
  if (broad == "brute-force" || broad == "sap") {
    s.broadPhase = broad == "sap" ? Settings::BroadPhaseMethod::SweepAndPrune : Settings::BroadPhaseMethod::BruteForce;
  } else {
    w.fail("broad_phase", "expected \"sap\" or \"brute-force\", got \"" + broad + "\"");
  }
  s.contactMargin = w.number("contact_margin", s.contactMargin);
  if (w.has("contact_recycle_distance")) {
    const nlohmann::json& recycle = w.raw("contact_recycle_distance");
    if (recycle.is_string()) {
      if (recycle.get<std::string>() != "auto") {
        w.fail("contact_recycle_distance", "expected \"auto\" or a distance in [0, 1] m, got \"" + recycle.get<std::string>() + "\"");
      }
      s.contactRecycleDistance = kAutoRecycleDistance;
    } else {
      s.contactRecycleDistance = w.number("contact_recycle_distance", s.contactRecycleDistance);
      if (s.contactRecycleDistance < 0.0) {
        w.fail("contact_recycle_distance", "expected \"auto\" or a distance in [0, 1] m (0: collide every pair every step)");
      }
    }
  }
  const std::string solver = w.string("solver", contactSolverName(s.solver));
  if (solver == "pgs" || solver == "soft-step" || solver == "lcp") {
    s.solver = solver == "pgs"   ? Settings::ContactSolverMethod::Pgs
               : solver == "lcp" ? Settings::ContactSolverMethod::Lcp
                                 : Settings::ContactSolverMethod::SoftStep;
  } else {
    w.fail("solver", "expected \"soft-step\", \"pgs\" or \"lcp\", got \"" + solver + "\"");
  }
  const std::string friction = w.string("friction", frictionModelName(s.friction));
  if (!parseFrictionModel(friction, s.friction)) {
    w.fail("friction", "expected \"cone\" or \"seed000\", got \"" + friction + "\"");
  }
  const std::string meshContact = w.string("mesh_contact", meshContactName(s.meshContact));
  if (meshContact == "triangles" || meshContact == "samples") {
    s.meshContact = meshContact == "triangles" ? Settings::MeshContact::Triangles : Settings::MeshContact::Samples;
  } else {
    w.fail("mesh_contact", "expected \"samples\" or \"triangles\", got \"" + meshContact + "\"");
  }
  const auto integer = [&](const char* key, int fallback) {
    if (!w.has(key)) return fallback;
    const double x = w.number(key, fallback);
    // Each says what it got (issue 56: substeps = 10**30 and 2.5 were both "expected an integer");
    // checkSettings then holds each key to its own range.
    if (x != std::floor(x)) w.fail(key, "expected an integer, got " + formatNumber(x));
    if (std::abs(x) > static_cast<double>(kMaxCount)) {
      w.fail(key, "expected an integer no larger than " + formatNumber(static_cast<double>(kMaxCount)) + " in magnitude, got " + formatNumber(x));
    }
    return static_cast<int>(x);
  };
  s.substeps = integer("substeps", s.substeps);
  if (w.has("threads")) {
    const double threads = w.number("threads", s.threads);
    if (threads != std::floor(threads) || !(threads >= 1.0 && threads <= kMaxThreads)) {
      w.fail("threads", "expected a whole number of threads in [1, " + std::to_string(kMaxThreads) + "]");
    }
    s.threads = static_cast<int>(threads);
  }
  s.contactHertz = w.number("contact_hertz", s.contactHertz);
  s.contactDampingRatio = w.number("contact_damping_ratio", s.contactDampingRatio);
  s.contactPushSpeed = w.number("contact_push_speed", s.contactPushSpeed);
  s.velocityIterations = integer("velocity_iterations", s.velocityIterations);
  s.positionIterations = integer("position_iterations", s.positionIterations);
  s.restitutionThreshold = w.number("restitution_threshold", s.restitutionThreshold);
  s.hitEventSpeed = w.number("hit_event_speed", s.hitEventSpeed);
  s.contactSlop = w.number("contact_slop", s.contactSlop);
  s.positionCorrection = w.number("position_correction", s.positionCorrection);
  s.warmStarting = w.boolean("warm_starting", s.warmStarting);
  s.warmStartDistance = w.number("warm_start_distance", s.warmStartDistance);
  s.respondToContacts = w.boolean("response", s.respondToContacts);
  s.logQueries = w.boolean("log_queries", s.logQueries);
  const int capacity = integer("query_log_capacity", static_cast<int>(s.queryLogCapacity));
  s.queryLogCapacity = capacity < 1 ? 0 : static_cast<std::size_t>(capacity);
  s.skipIdleStages = w.boolean("skip_idle_stages", s.skipIdleStages);
  const std::string integrator = w.string("integrator", integratorName(s.integrator));
  if (!parseIntegrator(integrator, s.integrator)) {
    std::string names;
    for (const std::string& n : integratorNames()) names += (names.empty() ? "" : ", ") + n;
    const std::string near = nearestKey(integrator, integratorNames());
    const std::string hint = near.empty() ? "" : " (did you mean \"" + near + "\"?)";
    w.fail("integrator", "unknown integrator \"" + integrator + "\"" + hint + "; expected one of " + names);
  }
  if (const SettingsProblem problem = checkSettings(s)) w.fail(problem.key.c_str(), problem.expectation);
}

void parseWorldBlock(const JsonObject& w, Scene& scene) {
  parseWorldSettings(w, scene.settings);
  scene.threadsGiven = w.has("threads");
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

void parseViewFields(const JsonObject& v, ViewDesc& view) {
  if (v.has("camera")) {
    const JsonObject c = v.object("camera", kCameraKeys);
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
        s[0].get<long long>() < kMinFrameSide || s[1].get<long long>() < kMinFrameSide || s[0].get<long long>() > kMaxFrameSide ||
        s[1].get<long long>() > kMaxFrameSide) {
      v.fail("size", "expected [width, height] in pixels, each an integer in [16, 8192]");
    }
    view.width = s[0].get<int>();
    view.height = s[1].get<int>();
    if (view.width % 2 != 0 || view.height % 2 != 0) v.fail("size", "H.264 in yuv420p needs even width and height");
  }
  view.fps = v.positiveInt("fps", view.fps);
  if (view.fps > kMaxFramesPerSecond) v.fail("fps", "expected at most " + std::to_string(kMaxFramesPerSecond) + " frames per second");
  view.overlay = v.boolean("overlay", view.overlay);
  if (v.has("panel")) {
    const std::string panel = v.string("panel", "");
    if (panel == "compact") view.panel = ViewDesc::Panel::Compact;
    else if (panel == "full") view.panel = ViewDesc::Panel::Full;
    else if (panel == "off") view.panel = ViewDesc::Panel::Off;
    else v.fail("panel", "expected \"compact\", \"full\" or \"off\", got \"" + panel + "\"");
  }
  view.wireframe = v.boolean("wireframe", view.wireframe);
  view.axes = v.boolean("axes", view.axes);
  view.grid = v.boolean("grid", view.grid);
  view.aabbs = v.boolean("aabbs", view.aabbs);
  view.contacts = v.boolean("contacts", view.contacts);
  view.vertices = v.boolean("vertices", view.vertices);
  view.instancing = v.boolean("instancing", view.instancing);
  view.follow = v.boolean("follow", view.follow);
  view.caption = v.string("caption", view.caption);
  if (v.has("plots")) {
    const nlohmann::json& plots = v.raw("plots");
    std::string names;
    for (const std::string& q : kPlotQuantities) names += (names.empty() ? "" : ", ") + q;
    if (!plots.is_array() || plots.empty() || plots.size() > kPlotQuantities.size()) {
      v.fail("plots", "expected an array of 1 to " + std::to_string(kPlotQuantities.size()) + " of " + names);
    }
    view.plots.clear();
    for (const nlohmann::json& p : plots) {
      const std::string name = p.is_string() ? p.get<std::string>() : p.dump();
      if (std::find(kPlotQuantities.begin(), kPlotQuantities.end(), name) == kPlotQuantities.end()) {
        v.fail("plots", "unknown quantity " + name + "; expected one of " + names);
      }
      if (std::find(view.plots.begin(), view.plots.end(), name) != view.plots.end()) v.fail("plots", name + " is listed twice");
      view.plots.push_back(name);
    }
  }
  const std::string of = v.string("plot_of", view.plotSelected ? "selected" : "scene");
  if (of != "scene" && of != "selected") v.fail("plot_of", "expected \"scene\" or \"selected\", got \"" + of + "\"");
  view.plotSelected = of == "selected";
  if (v.has("plot_seconds")) view.plotSeconds = v.positiveNumber("plot_seconds", view.plotSeconds);
  if (view.plotSeconds > kMaxPlotSeconds) v.fail("plot_seconds", "expected at most " + formatNumber(kMaxPlotSeconds) + " s of history");
}

BodyBlock parseBodyBlock(const nlohmann::json& body, const std::string& file, const std::string& path,
                         const std::string& baseDir, const Settings& settings, std::size_t index) {
  nlohmann::json named = body;
  if (named.is_object() && !named.contains("name")) named["name"] = "body" + std::to_string(index);
  const JsonObject b(named, file, path, scene_detail::kBodyKeys);
  // The body is parsed as the only one of a scene that never ends, so that its scripts refer to
  // body 0 and a force without "end" never stops; both are moved to `index` below.
  Scene scene;
  scene.file = file;
  scene.settings = settings;
  scene.duration = std::numeric_limits<double>::infinity();
  const std::optional<Vec3> color = scene_detail::parseBody(b, baseDir, scene);
  scene_detail::parseScripts(b, 0, scene);
  cookScene(scene);
  BodyBlock block{scene.bodies.front(), scene.inertiaMethods.front(), std::move(scene.forces), std::move(scene.poseEvents), std::move(scene.springs),
                   std::move(scene.motions), color};
  for (ScriptedForce& f : block.forces) f.body = sceneBodyId(index);
  for (PoseEvent& e : block.poseEvents) e.body = sceneBodyId(index);
  for (Spring& s : block.springs) s.body = sceneBodyId(index);
  for (KinematicMotion& m : block.motions) m.body = sceneBodyId(index);
  return block;
}

SpawnerDef parseSpawnerBlock(const nlohmann::json& block, const std::string& file, const std::string& path,
                             const std::string& baseDir, const Settings& settings, std::optional<Vec3>* color) {
  const JsonObject s(block, file, path, scene_detail::kSpawnKeys);
  if (!s.has("period")) s.fail("period", "expected the time between bursts [s] (a spawner adds bodies while the World steps)");
  Scene scene;
  scene.file = file;
  scene.settings = settings;
  scene.duration = std::numeric_limits<double>::infinity();
  double vertices = 0.0;
  scene_detail::parseSpawn(s, baseDir, scene, nullptr, vertices);
  cookScene(scene);
  if (color != nullptr) {
    const auto given = scene.colors.bySpawner.find(scene.spawners.at(0).name);
    *color = given == scene.colors.bySpawner.end() ? std::nullopt : std::optional<Vec3>(given->second);
  }
  return scene.spawners.at(0);
}

ScriptedForce parseForceBlock(const nlohmann::json& force, const std::string& file, const std::string& path,
                              std::size_t index, const Mat3& fileAxes) {
  return scene_detail::parseForce(JsonObject(force, file, path, scene_detail::kForceKeys), index, fileAxes,
                                  std::numeric_limits<double>::infinity());
}

std::pair<Plane, Material> parsePlaneBlock(const nlohmann::json& plane, const std::string& file, const std::string& path) {
  return scene_detail::parsePlane(JsonObject(plane, file, path, scene_detail::kPlaneKeys));
}

void parseViewBlock(const nlohmann::json& block, const std::string& file, const std::string& path, ViewDesc& view) {
  parseViewFields(JsonObject(block, file, path, {"camera", "overlay", "wireframe", "axes", "grid", "caption"}), view);
}

JointDef parseJointBlock(const nlohmann::json& joint, const std::string& file, const std::string& path, const World& world) {
  scene_detail::JointBodies bodies;
  for (const RigidBody& b : world.bodies()) {
    bodies.names.push_back(b.name());
    bodies.dynamic.push_back(b.isDynamic());
    bodies.ids.push_back(world.idAt(bodies.ids.size()));
  }
  return scene_detail::parseJoint(JsonObject(joint, file, path, scene_detail::kJointKeys), bodies, world.settings());
}

void checkPoseRanges(const std::string& call, const Vec3* position, const Vec3* velocity, const Vec3* angularVelocity,
                     double radius) {
  if (position && !(position->cwiseAbs().maxCoeff() <= kMaxCoordinate)) {
    throw InputError(call, "position", "expected coordinates within " + formatNumber(kMaxCoordinate) +
                                           " m of the origin; " + kFarFromOrigin);
  }
  if (velocity && !(velocity->stableNorm() <= kMaxSpeed)) {
    throw InputError(call, "velocity", "|v| = " + formatNumber(velocity->stableNorm()) + " m/s; expected less than the speed of light");
  }
  if (angularVelocity && !(angularVelocity->stableNorm() * radius <= kMaxSpeed)) {
    throw InputError(call, "angular_velocity", "its surface moves at |omega| r = " + formatNumber(angularVelocity->stableNorm()) +
                                                   " rad/s x " + formatNumber(radius) + " m, faster than light; expected a smaller spin");
  }
}

}  // namespace rbsim
