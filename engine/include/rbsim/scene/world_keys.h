#pragma once
// The keys of a scene's "world" and "view" blocks (scene_keys.h): names, types, ranges and a line
// each. scene_parts.cpp reads the blocks; the ranges are the constants checkSettings and
// parseViewFields check against.
#include <string>
#include <vector>

#include "rbsim/integrate/integrator.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/scene/scene_keys.h"
#include "rbsim/scene/view_desc.h"
#include "rbsim/settings/settings.h"

namespace rbsim {

inline constexpr const char* kInertiaMethodNames[] = {"cube", "exact"};
inline constexpr const char* kBroadPhaseNames[] = {"sap", "brute-force"};
inline constexpr const char* kContactSolverNames[] = {"soft-step", "pgs", "lcp"};
inline constexpr const char* kFrictionModelNames[] = {"cone", "seed000"};
inline constexpr const char* kMeshContactNames[] = {"samples", "triangles"};
inline constexpr const char* kAutoName[] = {"auto"};

inline constexpr SceneKey kWorldKeyTable[] = {
    key("gravity", KeyType::Vec3, "gravitational acceleration [m/s^2], |g| at most 1e13").magnitude(kMaxGravity),
    key("dt", KeyType::Number, "time step [s], in [1e-6, 0.1]").within(kMinTimeStep, kMaxTimeStep),
    key("integrator", KeyType::String, "how free bodies are advanced in time").oneOf(integratorNames),
    key("drift_correction", KeyType::Boolean, "re-orthonormalise euler-matrix's R each step (false only with euler-matrix)"),
    key("inertia", KeyType::String, "default inertia method: exact polyhedral integrals or the bounding-box cube").oneOf(kInertiaMethodNames),
    key("duration", KeyType::Number, "simulated time [s]; at most 1e9 steps").above(0.0),
    key("steps", KeyType::Integer, "number of steps, instead of duration").within(1.0, static_cast<double>(kMaxCount)),
    key("sleep", KeyType::Boolean, "let slow bodies sleep"),
    key("sleep_linear_speed", KeyType::Number, "below this speed a body may sleep [m/s]").atLeast(0.0),
    key("sleep_angular_speed", KeyType::Number, "below this turning rate a body may sleep [rad/s]").atLeast(0.0),
    key("time_to_sleep", KeyType::Number, "how long a body must be slow before it sleeps [s]").above(0.0),
    key("collisions", KeyType::Boolean, "detect collisions"),
    key("ccd", KeyType::Boolean, "continuous collision detection for fast bodies"),
    key("ccd_motion_fraction", KeyType::Number, "a step's motion, as a fraction of the thinnest extent, past which ccd sweeps").above(0.0),
    key("broad_phase", KeyType::String, "candidate pairs by sweep and prune or by testing every pair").oneOf(kBroadPhaseNames),
    key("contact_margin", KeyType::Number, "distance within which a pair counts as touching [m]").within(0.0, kMaxContactTolerance),
    key("contact_recycle_distance", KeyType::NumberOrChoice, "\"auto\" or how far a pair may move and keep its manifold [m]; 0: off")
        .within(0.0, kMaxContactTolerance).oneOf(kAutoName),
    key("solver", KeyType::String, "contact solver").oneOf(kContactSolverNames),
    key("friction", KeyType::String, "friction model: the cone, or seed 000's static-then-kinetic impulse").oneOf(kFrictionModelNames),
    key("mesh_contact", KeyType::String, "how two non-convex meshes meet: grid samples or triangle tests").oneOf(kMeshContactNames),
    key("substeps", KeyType::Integer, "soft step's substeps a step").within(1.0, kMaxSubsteps),
    key("contact_hertz", KeyType::Number, "soft contact stiffness as a frequency [Hz]").atLeast(0.0),
    key("contact_damping_ratio", KeyType::Number, "soft contact damping ratio").atLeast(0.0),
    key("contact_push_speed", KeyType::Number, "fastest a soft contact pushes bodies apart [m/s]").above(0.0),
    key("velocity_iterations", KeyType::Integer, "PGS velocity sweeps a step").within(1.0, kMaxSolverIterations),
    key("position_iterations", KeyType::Integer, "PGS position sweeps a step").within(0.0, kMaxSolverIterations),
    key("restitution_threshold", KeyType::Number, "approaches slower than this do not bounce [m/s]").atLeast(0.0),
    key("hit_event_speed", KeyType::Number, "slowest approach a contact hit event reports [m/s]").atLeast(0.0),
    key("contact_slop", KeyType::Number, "penetration left uncorrected [m]").within(0.0, kMaxContactTolerance),
    key("position_correction", KeyType::Number, "PGS share of the penetration corrected a step").within(0.0, 1.0),
    key("warm_starting", KeyType::Boolean, "start the solver from the last step's impulses"),
    key("warm_start_distance", KeyType::Number, "farthest a contact point may move and keep its impulse [m]").atLeast(0.0),
    key("response", KeyType::Boolean, "respond to contacts (false: detect only)"),
    key("log_queries", KeyType::Boolean, "keep the last narrow-phase queries"),
    key("query_log_capacity", KeyType::Integer, "narrow-phase queries the log keeps").within(1.0, static_cast<double>(kMaxQueryLogCapacity)),
    key("skip_idle_stages", KeyType::Boolean, "skip the stages a step has no work for"),
    key("threads", KeyType::Integer, "worker threads of a step (default: the machine's cores)").within(1.0, kMaxThreads),
    key("particle_integrator", KeyType::String, "how particles are advanced in time").oneOf(particleIntegratorNames),
};
// The keys of a scene's "world" block.
inline constexpr KeyTable kWorldKeys{kWorldKeyTable, "the physics: gravity, time step, solver and their settings"};

// Beyond this a video shows nothing a person can see, and it is most likely a typo.
inline constexpr int kMaxFramesPerSecond = 240;  // [1/s]
// A plot wider than an hour shows a minute as a few pixels; its history would be kept for nothing.
inline constexpr double kMaxPlotSeconds = 3600.0;  // [s]
// A frame's width and height: below 16 px nothing is legible, above 8192 px a frame is 256 MB.
inline constexpr int kMinFrameSide = 16;    // [px]
inline constexpr int kMaxFrameSide = 8192;  // [px]

inline std::vector<std::string> plotQuantityNames() { return kPlotQuantities; }

inline constexpr const char* kPanelNames[] = {"compact", "full", "off"};
inline constexpr const char* kPlotOfNames[] = {"scene", "selected"};
inline constexpr const char* kAxisNames[] = {"x", "y", "z"};

inline constexpr SceneKey kCameraKeyTable[] = {
    key("eye", KeyType::Vec3, "camera position [m]"),
    key("target", KeyType::Vec3, "point looked at [m]; not the eye"),
    key("up", KeyType::Vec3, "up direction; not along the view direction"),
    key("fov_deg", KeyType::Number, "vertical field of view [degrees]").above(0.0).below(180.0),
};
inline constexpr KeyTable kCameraKeys{kCameraKeyTable, "where the camera stands and looks"};

inline constexpr SceneKey kSdfSliceKeyTable[] = {
    key("body", KeyType::String, "name of a body with a signed distance grid").needed(),
    key("axis", KeyType::String, "the slice's normal, a body axis").oneOf(kAxisNames),
    key("offset", KeyType::Number, "along the axis from the centre of mass at t = 0, within the grid [m]"),
    key("sweep_to", KeyType::Number, "offset at the scene's end, moved linearly in time [m]"),
};
inline constexpr KeyTable kSdfSliceKeys{kSdfSliceKeyTable, "a layer of one body's signed distance grid shown beside the scene"};

inline constexpr SceneKey kViewKeyTable[] = {
    key("camera", KeyType::Object, "the camera").of(kCameraKeys),
    key("size", KeyType::IntegerArray, "[width, height] in pixels, each even and in [16, 8192]").sized(2).within(kMinFrameSide, kMaxFrameSide),
    key("fps", KeyType::Integer, "frames per simulated second").within(1.0, kMaxFramesPerSecond),
    key("overlay", KeyType::Boolean, "draw the overlay"),
    key("panel", KeyType::String, "how much of the variables panel shows").oneOf(kPanelNames),
    key("wireframe", KeyType::Boolean, "draw edges only"),
    key("axes", KeyType::Boolean, "draw the world axes"),
    key("grid", KeyType::Boolean, "draw the ground grid"),
    key("aabbs", KeyType::Boolean, "draw bounding boxes, red when in a pair"),
    key("contacts", KeyType::Boolean, "draw contact points and normals"),
    key("vertices", KeyType::Boolean, "draw each body's vertex list as dots"),
    key("instancing", KeyType::Boolean, "draw bodies that share a mesh as instances of it"),
    key("selected", KeyType::String, "name of the body shown in the overlay"),
    key("follow", KeyType::Boolean, "move the camera with the selected body"),
    key("caption", KeyType::String, "text shown in the frame"),
    key("plots", KeyType::StringArray, "quantities plotted over time, each once").oneOf(plotQuantityNames).nonEmpty(),
    key("plot_of", KeyType::String, "plot the whole scene or the selected body").oneOf(kPlotOfNames),
    key("plot_seconds", KeyType::Number, "history a plot shows [s]").above(0.0).atMost(kMaxPlotSeconds),
    key("sdf_slice", KeyType::Object, "a slice of a body's signed distance grid").of(kSdfSliceKeys),
};
// The keys of a scene's "view" block.
inline constexpr KeyTable kViewKeys{kViewKeyTable, "how the scene is shown: camera, frame size, overlay, plots"};

// A "compare" block: the run command (app/run/phase.cpp) makes a world per value of one key and
// shows them side by side; the engine's parser never sees it.
inline constexpr SceneKey kCompareKeyTable[] = {
    key("key", KeyType::String, "the key compared, in --set form (world.solver, bodies.box.mass)").needed(),
    key("values", KeyType::Any, "2 or more values of the key, each different: one world each").needed(),
    key("labels", KeyType::StringArray, "a caption per value"),
};
inline constexpr KeyTable kCompareKeys{kCompareKeyTable, "worlds that differ in one key, side by side"};

}  // namespace rbsim
