#pragma once
// Scene-file parsing of bodies and what hangs on them (scripted forces, pose events, springs),
// of planes, and of spawn blocks that create many bodies from one template. Internal to scene/.
#include <string>
#include <utility>

#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"

namespace rbsim::scene_detail {

inline constexpr std::initializer_list<const char*> kBodyKeys = {
    "name", "shape", "mass", "density", "inertia", "position", "orientation", "velocity",
    "angular_velocity", "color", "static", "kinematic", "forces", "set_pose", "springs", "restitution",
    "friction_static", "friction_kinetic", "fracture", "sdf"};

// The material keys of a body or a plane ("restitution", "friction_static", "friction_kinetic"),
// each defaulting to Material's.
Material parseMaterial(const JsonObject& o);

// The body's orientation for an orientation of the file's axes: q_file E (mass/mass_model.h).
Quat toBodyOrientation(const BodyDef& def, const Quat& fileOrientation);

// Appends the body described by `b` to scene.bodies (and its inertia method name).
void parseBody(const JsonObject& b, const std::string& baseDir, Scene& scene);
inline constexpr std::initializer_list<const char*> kForceKeys = {"force", "point", "force_frame", "point_frame", "start",
                                                                 "end"};
// One entry of a body's "forces", on body `index` whose file axes are `fileAxes`; without "end"
// it acts until `duration`.
ScriptedForce parseForce(const JsonObject& f, std::size_t index, const Mat3& fileAxes, double duration);
// Appends the forces, pose events and springs of body `index`.
void parseScripts(const JsonObject& b, std::size_t index, Scene& scene);
// The body named by o[key]; fails naming the field if there is none.
std::size_t findBody(const std::vector<BodyDef>& bodies, const JsonObject& o, const char* key);
inline constexpr std::initializer_list<const char*> kPlaneKeys = {"normal", "point", "restitution", "friction_static",
                                                                 "friction_kinetic"};
// One plane: {"normal": [0, 1, 0], "point": [0, 0, 0], material keys}.
std::pair<Plane, Material> parsePlane(const JsonObject& p);
// "planes": [{...}, ...]
void parsePlanes(const JsonObject& root, Scene& scene);
// "spawn": [{"count", "seed", "name", "body": {...}, "region": {"min", "max"}, "speed": [lo, hi],
//            "angular_speed": [lo, hi]}, ...]
void parseSpawns(const JsonObject& root, const std::string& baseDir, Scene& scene);

}  // namespace rbsim::scene_detail
