#pragma once
// One block of a scene file read on its own, with the keys, checks and messages of a whole file:
// for programs that build a World piece by piece instead of loading a file (the Python module,
// python/). Every function throws InputError naming `file`, the block's path and the key.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"
#include "rbsim/scene/world_keys.h"

namespace rbsim {

// The "world" block into scene.settings, scene.duration and scene.particleIntegrator.
void parseWorldBlock(const JsonObject& w, Scene& scene);
// The Settings keys of a "world" block onto `settings`, absent keys keeping its values, then
// checked as a whole (checkSettings): what a running World's settings may take (Python's
// World.dt = ..., World.gravity = ...).
void parseWorldSettings(const JsonObject& w, Settings& settings);
// The "world" block that parseWorldBlock reads back into the same settings, duration and particle
// integrator: every key of kWorldKeys but "steps" (the duration says it).
nlohmann::json worldBlockJson(const Scene& scene);

// A body block (the keys of one entry of "bodies") and what hangs on it, for the body that will
// be number `index` of a World whose settings are `settings` (its default inertia method).
// Without "name" the body is called "body<index>", as in a file. A force without "end" acts for
// ever (in a file, until the scene's duration).
struct BodyBlock {
  BodyDef def;
  std::string inertiaMethod;  // as resolved: "cube" or "exact"
  std::vector<ScriptedForce> forces;  // each acting on `index`
  std::vector<PoseEvent> poseEvents;
  std::vector<Spring> springs;
  std::vector<KinematicMotion> motions;  // at most one
  std::optional<Vec3> color;             // its "color" (Scene::colors), when given
};
BodyBlock parseBodyBlock(const nlohmann::json& body, const std::string& file, const std::string& path,
                         const std::string& baseDir, const Settings& settings, std::size_t index);

// A spawn block (the keys of one entry of "spawn") with a "period": the spawner it describes, for a
// World whose settings are `settings` (its default inertia method). Without "period" it is an
// InputError: a World adds bodies now with addBody.
// `color`, when not null, receives the copies' "color" (Scene::colors), when given.
SpawnerDef parseSpawnerBlock(const nlohmann::json& block, const std::string& file, const std::string& path,
                             const std::string& baseDir, const Settings& settings, std::optional<Vec3>* color = nullptr);

// A force block (the keys of one entry of a body's "forces") on body `index`, whose file axes
// are `fileAxes` (FileFrame::axes); without "end" it acts for ever.
ScriptedForce parseForceBlock(const nlohmann::json& force, const std::string& file, const std::string& path,
                              std::size_t index, const Mat3& fileAxes);

// A plane block: {"normal", "point", "restitution", "friction_static", "friction_kinetic"}.
std::pair<Plane, Material> parsePlaneBlock(const nlohmann::json& plane, const std::string& file, const std::string& path);

// A joint block (the keys of one entry of "joints"), its body_a and body_b naming bodies of
// `world`, whose settings must be the soft step's.
JointDef parseJointBlock(const nlohmann::json& joint, const std::string& file, const std::string& path, const World& world);

// The fields of a view block but "selected" (a body of the file: the caller's) into `view`.
void parseViewFields(const JsonObject& v, ViewDesc& view);
// What a single picture of a view block uses, over `view`: "camera", "overlay", "wireframe",
// "axes", "grid" and "caption" (a picture has no frame rate, its size is the renderer's, and it
// has no history to plot).
// A pose set by hand (Python's World.set_pose) within a scene's ranges: coordinates within 1e6 m
// of the origin, |v| and the surface's speed of turning |omega| radius below the speed of light.
// InputError naming `call` and the field ("position", "velocity", "angular_velocity").
void checkPoseRanges(const std::string& call, const Vec3* position, const Vec3* velocity, const Vec3* angularVelocity,
                     double radius);

void parseViewBlock(const nlohmann::json& block, const std::string& file, const std::string& path, ViewDesc& view);

}  // namespace rbsim
