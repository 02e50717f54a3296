#include "scene/scene.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/input_error.h"
#include "io/obj_loader.h"
#include "mass/mass_model.h"
#include "scene/json_fields.h"

namespace rbsim {

namespace {

// Beyond this a video shows nothing a person can see, and it is most likely a typo.
constexpr int kMaxFramesPerSecond = 240;  // [1/s]

// Line and column of a byte offset, for JSON syntax errors.
std::string lineAndColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

Frame parseFrame(const JsonObject& o, const char* key, Frame fallback) {
  const std::string name = o.string(key, fallback == Frame::Body ? "body" : "world");
  if (name == "body") return Frame::Body;
  if (name == "world") return Frame::World;
  o.fail(key, "expected \"body\" or \"world\", got \"" + name + "\"");
}

Mesh parseShape(const JsonObject& body, const std::string& baseDir) {
  const JsonObject shape = body.object("shape", {"type", "extents", "file", "scale"});
  const std::string type = shape.requiredString("type");
  if (type == "box") return makeBox(shape.positiveVec3("extents"));
  if (type == "mesh") {
    const std::string file = shape.requiredString("file");
    const std::filesystem::path full = std::filesystem::path(baseDir) / file;
    Mesh mesh;
    try {
      mesh = loadObj(full.lexically_normal().string());
    } catch (const InputError& e) {
      throw InputError(shape.file(), shape.pathOf("file"), e.what());
    }
    const double scale = shape.positiveNumber("scale", 1.0);
    for (Vec3& p : mesh.vertices) p *= scale;
    return mesh;
  }
  shape.fail("type", "expected \"box\" or \"mesh\", got \"" + type + "\"");
}

std::size_t findBody(const std::vector<BodyDef>& bodies, const JsonObject& o, const char* key) {
  const std::string name = o.requiredString(key);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == name) return i;
  }
  o.fail(key, "no body is named \"" + name + "\"");
}

void parseBody(const JsonObject& b, const std::string& baseDir, Scene& scene) {
  BodyDef def;
  def.name = b.string("name", "body" + std::to_string(scene.bodies.size()));
  InertiaMethod method = scene.settings.inertia;
  if (b.has("inertia") && !parseInertiaMethod(b.string("inertia", ""), method)) {
    b.fail("inertia", "expected \"cube\" or \"exact\"");
  }
  Mesh mesh = parseShape(b, baseDir);
  if (b.has("mass")) b.positiveNumber("mass", 1.0);        // type and sign errors name the field
  if (b.has("density")) b.positiveNumber("density", 1.0);
  try {
    const MassModel model = buildMassModel(std::move(mesh), b.optionalPositive("mass"),
                                           b.optionalPositive("density"), method);
    def.mesh = model.mesh;
    def.mass = model.mass;
    def.inertiaBody = model.inertiaBody;
  } catch (const InputError& e) {
    throw InputError(b.file(), b.pathOf(e.field().c_str()), e.problem());
  }
  def.position = b.vec3("position", Vec3::Zero());
  def.orientation = b.optionalOrientation("orientation").value_or(Quat::Identity());
  def.velocity = b.vec3("velocity", Vec3::Zero());
  def.angularVelocity = b.vec3("angular_velocity", Vec3::Zero());
  def.color = b.vec3("color", def.color);
  if (def.color.minCoeff() < 0.0 || def.color.maxCoeff() > 1.0) b.fail("color", "components must lie in [0, 1]");
  scene.bodies.push_back(def);
  scene.inertiaMethods.emplace_back(inertiaMethodName(method));
}

void parseScripts(const JsonObject& b, std::size_t index, Scene& scene) {
  for (const JsonObject& f : b.objectArray("forces", {"force", "point", "force_frame", "point_frame", "start", "end"})) {
    ScriptedForce force;
    force.body = index;
    force.force = f.vec3("force", Vec3::Zero());
    force.point = f.vec3("point", Vec3::Zero());
    force.forceFrame = parseFrame(f, "force_frame", Frame::World);
    force.pointFrame = parseFrame(f, "point_frame", Frame::Body);
    force.start = f.number("start", 0.0);
    force.end = f.number("end", scene.duration);
    if (force.start < 0.0) f.fail("start", "expected a time >= 0 s");
    if (!(force.end > force.start)) f.fail("end", "expected a time after \"start\"");
    scene.forces.push_back(force);
  }
  for (const JsonObject& p : b.objectArray("set_pose", {"time", "position", "orientation", "velocity", "angular_velocity"})) {
    PoseEvent event;
    event.body = index;
    event.time = p.requiredNumber("time");
    if (event.time < 0.0) p.fail("time", "expected a time >= 0 s");
    event.position = p.optionalVec3("position");
    event.orientation = p.optionalOrientation("orientation");
    event.velocity = p.optionalVec3("velocity");
    event.angularVelocity = p.optionalVec3("angular_velocity");
    scene.poseEvents.push_back(event);
  }
}

void parseView(const JsonObject& root, Scene& scene) {
  if (!root.has("view")) return;
  const JsonObject v = root.object("view", {"camera", "size", "fps", "overlay", "wireframe", "axes", "grid", "selected", "caption"});
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
  view.caption = v.string("caption", view.caption);
  if (v.has("selected")) view.selected = findBody(scene.bodies, v, "selected");
}

}  // namespace

std::uint64_t Scene::stepCount() const {
  return static_cast<std::uint64_t>(std::llround(duration / settings.timeStep));
}

Scene parseScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir) {
  const JsonObject root(document, file, "", {"title", "world", "view", "bodies"});
  Scene scene;
  scene.file = file;
  scene.title = root.string("title", std::filesystem::path(file).stem().string());
  if (root.has("world")) {
    const JsonObject w = root.object("world", {"gravity", "dt", "integrator", "inertia", "duration", "steps", "sleep"});
    scene.settings.gravity = w.vec3("gravity", scene.settings.gravity);
    scene.settings.timeStep = w.positiveNumber("dt", scene.settings.timeStep);
    if (scene.settings.timeStep > kMaxTimeStep || scene.settings.timeStep < kMinTimeStep) {
      std::ostringstream expected;
      expected << "a time step of " << scene.settings.timeStep << " s is absurd; expected one in [" << kMinTimeStep
               << ", " << kMaxTimeStep << "] s";
      w.fail("dt", expected.str());
    }
    scene.settings.allowSleep = w.boolean("sleep", scene.settings.allowSleep);
    const std::string integrator = w.string("integrator", integratorName(scene.settings.integrator));
    if (!parseIntegrator(integrator, scene.settings.integrator)) {
      std::string names;
      for (const std::string& n : integratorNames()) names += (names.empty() ? "" : ", ") + n;
      w.fail("integrator", "unknown integrator \"" + integrator + "\"; expected one of " + names);
    }
    const std::string inertia = w.string("inertia", inertiaMethodName(scene.settings.inertia));
    if (!parseInertiaMethod(inertia, scene.settings.inertia)) w.fail("inertia", "expected \"cube\" or \"exact\"");
    scene.duration = w.positiveNumber("duration", scene.duration);
    if (w.has("steps")) scene.duration = w.positiveInt("steps", 1) * scene.settings.timeStep;
  }
  const std::vector<JsonObject> bodies = root.objectArray(
      "bodies", {"name", "shape", "mass", "density", "inertia", "position", "orientation", "velocity",
                 "angular_velocity", "color", "forces", "set_pose"});
  if (bodies.empty()) throw InputError(file, "bodies", "expected a non-empty array of bodies");
  for (const JsonObject& b : bodies) parseBody(b, baseDir, scene);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (scene.bodies[i].name == scene.bodies[j].name) bodies[i].fail("name", "duplicate body name \"" + scene.bodies[i].name + "\"");
    }
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) parseScripts(bodies[i], i, scene);
  parseView(root, scene);
  return scene;
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the scene file (missing or unreadable)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path, lineAndColumn(text, e.byte == 0 ? 0 : e.byte - 1),
                     std::string("invalid JSON: ") + e.what());
  }
  for (const std::string& assignment : overrides) {
    try {
      applyOverride(document, assignment);
    } catch (const InputError& e) {
      throw InputError(path, "--set " + assignment, e.problem());
    }
  }
  return parseScene(document, path, std::filesystem::path(path).parent_path().string());
}

World buildWorld(const Scene& scene) {
  World world(scene.settings);
  for (const BodyDef& def : scene.bodies) world.addBody(def);
  for (const ScriptedForce& f : scene.forces) world.addForce(f);
  for (const PoseEvent& e : scene.poseEvents) world.addPoseEvent(e);
  return world;
}

}  // namespace rbsim
