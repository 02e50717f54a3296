// The engine's JavaScript API (issue 59), bound with Emscripten's embind: a World made from a
// scene's JSON (or a shipped scene's name), stepped, and read back as typed arrays. Everything a
// teacher's page needs to show a simulation: positions x and orientations q of every body, and
// every body's world-space vertices and triangles (seed 004: each transformed vertex readable).
//
//   const rbsim = await createRbsim();
//   const world = rbsim.World.fromScene("contact_stacking", ["world.dt=0.01"]);
//   world.step(60);
//   const x = world.positions();     // Float64Array [x0 y0 z0 x1 y1 z1 ...]
//   const q = world.orientations();  // Float64Array [w0 x0 y0 z0 ...]
//   world.delete();                  // embind objects live in the wasm heap until deleted
//
// A bad scene or key throws a JavaScript Error whose message is the native program's (the file,
// the field and what was expected), and the World it came from is unchanged. A scene that
// compares several settings side by side ("compare") is one World per value: phaseLabels names
// them, fromPhase builds each.
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "rbsim/scene/scene.h"
#include "run/phase.h"
#include "rbsim/world/ray_cast.h"
#include "rbsim/world/spring.h"
#include "rbsim/world/world.h"

namespace {

using emscripten::val;

// How far a pointer's ray looks for a body to grab [m].
constexpr double kMaxGrabDistance = 1e4;

// Where the packaged files sit in Emscripten's virtual file system (--preload-file, web/CMakeLists.txt).
const std::string kSceneFolder = "/assets/scenes";

[[noreturn]] void throwJsError(const std::string& message) {
  val::global("Error").new_(message).throw_();
}

// A JavaScript typed array holding a copy of `values` (a view would dangle when the heap grows).
template <typename T>
val copyToTypedArray(const char* type, const std::vector<T>& values) {
  val array = val::global(type).new_(values.size());
  array.call<void>("set", val(emscripten::typed_memory_view(values.size(), values.data())));
  return array;
}

class JsWorld {
 public:
  // A shipped scene by name ("contact_stacking"), or a path in the packaged file system.
  // `overrides`: an array of "key=value" strings, the native --set's (optional). A scene with a
  // "compare" block is several Worlds: fromPhase builds each.
  static JsWorld fromScene(const std::string& nameOrPath, const val& overrides) {
    const std::vector<std::string> assignments = toStrings(overrides);
    return guarded([&] {
      const rbsim::app::Phase phase = rbsim::app::loadPhase(scenePath(nameOrPath), assignments);
      if (phase.compared()) {
        throw std::invalid_argument(phase.file + ": compare: it compares " + std::to_string(phase.worlds.size()) + " Worlds (" +
                                    phase.compareKey + "); World.phaseLabels(scene) names them and World.fromPhase(scene, overrides, k) builds the k-th");
      }
      return JsWorld(phase.scene());
    });
  }
  static JsWorld fromSceneName(const std::string& nameOrPath) { return fromScene(nameOrPath, val::array()); }

  // World k of a scene's phase (app/run/phase.h): of a compared scene, the one with the k-th
  // value of its "compare" block applied; of a plain scene, k = 0 is the scene.
  static JsWorld fromPhase(const std::string& nameOrPath, const val& overrides, int k) {
    const std::vector<std::string> assignments = toStrings(overrides);
    return guarded([&] {
      const rbsim::app::Phase phase = rbsim::app::loadPhase(scenePath(nameOrPath), assignments);
      if (k < 0 || static_cast<std::size_t>(k) >= phase.worlds.size()) {
        throw std::invalid_argument(phase.file + ": World.fromPhase: world " + std::to_string(k) + " of " +
                                    std::to_string(phase.worlds.size()) + " (0 to " + std::to_string(phase.worlds.size() - 1) + " expected)");
      }
      return JsWorld(phase.worlds[static_cast<std::size_t>(k)].scene);
    });
  }

  // The captions of a phase's Worlds, as the video's panes show them ("PGS", "soft step"); one
  // empty label for a plain scene.
  static val phaseLabels(const std::string& nameOrPath, const val& overrides) {
    const std::vector<std::string> assignments = toStrings(overrides);
    const rbsim::app::Phase phase = guarded([&] { return rbsim::app::loadPhase(scenePath(nameOrPath), assignments); });
    val labels = val::array();
    for (const rbsim::app::PhaseWorld& w : phase.worlds) labels.call<void>("push", w.label);
    return labels;
  }
  static val phaseLabelsOf(const std::string& nameOrPath) { return phaseLabels(nameOrPath, val::array()); }

  // A scene's JSON text; its mesh paths are relative to the shipped scenes' folder.
  static JsWorld fromJson(const std::string& text, const val& overrides) {
    const std::vector<std::string> assignments = toStrings(overrides);
    return guarded([&] { return JsWorld(rbsim::parseSceneText(text, "scene.json", kSceneFolder, assignments)); });
  }
  static JsWorld fromJsonText(const std::string& text) { return fromJson(text, val::array()); }

  // Advances n steps; a step that fails leaves the World as it was before that step (world.h).
  void step(int n) {
    if (n < 0) throwJsError("World.step: the number of steps must be 0 or more, not " + std::to_string(n));
    guarded([&] {
      for (int i = 0; i < n; ++i) world_.step();
      return 0;
    });
  }

  int bodyCount() const { return static_cast<int>(world_.bodies().size()); }
  std::string bodyName(int i) const { return body(i).name(); }
  double time() const { return static_cast<double>(world_.stepCount()) * world_.settings().timeStep; }
  double timeStep() const { return world_.settings().timeStep; }
  double stepCount() const { return static_cast<double>(world_.stepCount()); }
  // The scene's own length [steps] (its duration at its dt), for a page that plays it through.
  double sceneSteps() const { return static_cast<double>(sceneSteps_); }

  val positions() const {
    std::vector<double> x;
    x.reserve(3 * world_.bodies().size());
    for (const rbsim::RigidBody& b : world_.bodies()) x.insert(x.end(), {b.position().x(), b.position().y(), b.position().z()});
    return copyToTypedArray("Float64Array", x);
  }

  val orientations() const {
    std::vector<double> q;
    q.reserve(4 * world_.bodies().size());
    for (const rbsim::RigidBody& b : world_.bodies()) {
      const rbsim::Quat& o = b.orientation();
      q.insert(q.end(), {o.w(), o.x(), o.y(), o.z()});
    }
    return copyToTypedArray("Float64Array", q);
  }

  // Body i's vertices in world space, p' = R p + x [m], three numbers a vertex.
  val vertices(int i) const {
    std::vector<double> p;
    for (const rbsim::Vec3& v : body(i).worldVertices()) p.insert(p.end(), {v.x(), v.y(), v.z()});
    return copyToTypedArray("Float64Array", p);
  }

  // Body i's triangles, three vertex indices each, counter-clockwise seen from outside.
  val triangles(int i) const {
    std::vector<std::uint32_t> t;
    for (const rbsim::Triangle& tri : body(i).mesh().triangles) t.insert(t.end(), tri.begin(), tri.end());
    return copyToTypedArray("Uint32Array", t);
  }

  // Starts dragging the body the ray origin + s direction meets first (the page's pointer), as
  // window mode does: a drag spring (world/spring.h) from the point hit to an anchor that
  // moveGrab moves. Returns the body's index, or -1 when the ray meets nothing, a plane or a body
  // that forces do not move (static or kinematic).
  int grab(double ox, double oy, double oz, double dx, double dy, double dz) {
    release();
    const std::optional<rbsim::WorldRayHit> hit =
        guarded([&] { return rbsim::rayCast(world_, rbsim::Vec3(ox, oy, oz), rbsim::Vec3(dx, dy, dz), kMaxGrabDistance); });
    if (!hit || hit->isPlane) return -1;
    const std::size_t index = world_.indexOf(hit->body);
    const rbsim::RigidBody& body = world_.bodies()[index];
    if (!body.isDynamic()) return -1;
    drag_ = rbsim::addSpring(world_, rbsim::dragSpring(hit->body, body, hit->point));
    rbsim::moveSpringAnchor(world_, *drag_, hit->point);  // wakes the body
    return static_cast<int>(index);
  }

  // Moves the drag's anchor to a world point [m]; nothing when no drag is on.
  void moveGrab(double x, double y, double z) {
    dropStaleDrag();
    if (drag_) guarded([&] { rbsim::moveSpringAnchor(world_, *drag_, rbsim::Vec3(x, y, z)); return 0; });
  }

  // Ends the drag, if one is on.
  void release() {
    dropStaleDrag();
    if (drag_) rbsim::removeSpring(world_, *drag_);
    drag_.reset();
  }

  // The dragged body's index, or -1.
  int grabbed() {
    dropStaleDrag();
    return drag_ ? static_cast<int>(world_.indexOf(rbsim::springs(world_)[rbsim::indexOf(world_, *drag_)].body)) : -1;
  }

  // The drag spring's anchor [m] (right after grab, the point hit), or an empty array.
  val grabAnchor() {
    dropStaleDrag();
    std::vector<double> anchor;
    if (drag_) {
      const rbsim::Vec3& a = rbsim::springs(world_)[rbsim::indexOf(world_, *drag_)].anchor;
      anchor = {a.x(), a.y(), a.z()};
    }
    return copyToTypedArray("Float64Array", anchor);
  }

  // World::stateHash as 16 hex digits: the same number the native program computes for the same
  // scene, dt and step count when the two builds agree bit for bit.
  std::string stateHash() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(world_.stateHash()));
    return text;
  }

 private:
  explicit JsWorld(const rbsim::Scene& scene) : world_(rbsim::buildWorld(scene)), sceneSteps_(scene.stepCount()) {}

  const rbsim::RigidBody& body(int i) const {
    if (i < 0 || i >= bodyCount()) {
      throwJsError("World: body index " + std::to_string(i) + " is out of range (the World has " +
                   std::to_string(bodyCount()) + " bodies)");
    }
    return world_.bodies()[static_cast<std::size_t>(i)];
  }

  // A shipped scene's name, or a path in the packaged file system as it is.
  static std::string scenePath(const std::string& nameOrPath) {
    return nameOrPath.find('/') == std::string::npos ? kSceneFolder + "/" + nameOrPath + ".json" : nameOrPath;
  }

  static std::vector<std::string> toStrings(const val& array) {
    if (!val::global("Array").call<bool>("isArray", array)) throwJsError("World: the overrides must be an array of \"key=value\" strings");
    std::vector<std::string> strings;
    const int n = array["length"].as<int>();
    for (int i = 0; i < n; ++i) {
      if (!array[i].isString()) throwJsError("World: override " + std::to_string(i) + " is not a string (\"key=value\" expected)");
      strings.push_back(array[i].as<std::string>());
    }
    return strings;
  }

  // The dragged body left the World (a kill volume, a lifetime) and took the spring with it.
  void dropStaleDrag() {
    if (drag_ && !rbsim::isValid(world_, *drag_)) drag_.reset();
  }

  // Runs f, turning a C++ exception into a JavaScript Error with its message.
  template <typename F>
  static auto guarded(F&& f) -> decltype(f()) {
    std::string message;
    try {
      return f();
    } catch (const std::exception& e) {
      message = e.what();
    }
    throwJsError(message);
  }

  rbsim::World world_;
  std::uint64_t sceneSteps_;
  std::optional<rbsim::SpringId> drag_;
};

}  // namespace

EMSCRIPTEN_BINDINGS(rbsim) {
  emscripten::class_<JsWorld>("World")
      .class_function("fromScene", &JsWorld::fromScene)
      .class_function("fromScene", &JsWorld::fromSceneName)
      .class_function("fromPhase", &JsWorld::fromPhase)
      .class_function("phaseLabels", &JsWorld::phaseLabels)
      .class_function("phaseLabels", &JsWorld::phaseLabelsOf)
      .class_function("fromJson", &JsWorld::fromJson)
      .class_function("fromJson", &JsWorld::fromJsonText)
      .function("step", &JsWorld::step)
      .function("bodyCount", &JsWorld::bodyCount)
      .function("bodyName", &JsWorld::bodyName)
      .function("time", &JsWorld::time)
      .function("timeStep", &JsWorld::timeStep)
      .function("stepCount", &JsWorld::stepCount)
      .function("sceneSteps", &JsWorld::sceneSteps)
      .function("positions", &JsWorld::positions)
      .function("orientations", &JsWorld::orientations)
      .function("vertices", &JsWorld::vertices)
      .function("triangles", &JsWorld::triangles)
      .function("grab", &JsWorld::grab)
      .function("moveGrab", &JsWorld::moveGrab)
      .function("release", &JsWorld::release)
      .function("grabbed", &JsWorld::grabbed)
      .function("grabAnchor", &JsWorld::grabAnchor)
      .function("stateHash", &JsWorld::stateHash);
}
