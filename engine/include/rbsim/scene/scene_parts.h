#pragma once
// One block of a scene file read on its own, with the keys, checks and messages of a whole file:
// for programs that build a World piece by piece instead of loading a file (the Python module,
// python/). Every function throws InputError naming `file`, the block's path and the key.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim {

// The keys of a scene's "world" block.
inline constexpr std::initializer_list<const char*> kWorldKeys = {
    "gravity", "dt", "integrator", "drift_correction", "inertia", "duration", "steps", "sleep", "sleep_linear_speed",
    "sleep_angular_speed", "time_to_sleep", "collisions", "ccd", "ccd_motion_fraction", "broad_phase",
    "contact_margin", "contact_recycle_distance", "solver", "friction", "mesh_contact", "substeps", "contact_hertz",
    "contact_damping_ratio", "contact_push_speed",
    "velocity_iterations", "position_iterations", "restitution_threshold", "hit_event_speed", "contact_slop", "position_correction",
    "warm_starting", "warm_start_distance", "response", "log_queries", "query_log_capacity", "skip_idle_stages", "threads",
    "particle_integrator"};

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
};
BodyBlock parseBodyBlock(const nlohmann::json& body, const std::string& file, const std::string& path,
                         const std::string& baseDir, const Settings& settings, std::size_t index);

// A spawn block (the keys of one entry of "spawn") with a "period": the spawner it describes, for a
// World whose settings are `settings` (its default inertia method). Without "period" it is an
// InputError: a World adds bodies now with addBody.
SpawnerDef parseSpawnerBlock(const nlohmann::json& block, const std::string& file, const std::string& path,
                             const std::string& baseDir, const Settings& settings);

// A force block (the keys of one entry of a body's "forces") on body `index`, whose file axes
// are `fileAxes` (FileFrame::axes); without "end" it acts for ever.
ScriptedForce parseForceBlock(const nlohmann::json& force, const std::string& file, const std::string& path,
                              std::size_t index, const Mat3& fileAxes);

// A plane block: {"normal", "point", "restitution", "friction_static", "friction_kinetic"}.
std::pair<Plane, Material> parsePlaneBlock(const nlohmann::json& plane, const std::string& file, const std::string& path);

// A joint block (the keys of one entry of "joints"), its body_a and body_b naming bodies of
// `world`, whose settings must be the soft step's.
JointDef parseJointBlock(const nlohmann::json& joint, const std::string& file, const std::string& path, const World& world);

inline constexpr std::initializer_list<const char*> kViewKeys = {
    "camera", "size", "fps", "overlay", "panel", "wireframe", "axes", "grid", "aabbs", "contacts", "vertices", "instancing", "selected", "follow",
    "caption", "plots", "plot_of", "plot_seconds", "sdf_slice"};
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
