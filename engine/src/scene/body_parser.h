#pragma once
// Scene-file parsing of bodies and what hangs on them (scripted forces, pose events, springs),
// of planes, and of spawn blocks that create many bodies from one template. Internal to scene/.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "rbsim/scene/cook.h"
#include "rbsim/scene/json_fields.h"
#include "rbsim/scene/scene.h"
#include "scene/spawn_keys.h"

namespace rbsim::scene_detail {

// The material keys of a body or a plane ("restitution", "friction_static", "friction_kinetic"),
// each defaulting to base's (Material's, or a running body's for World.set_body), each checked
// as setBodyMaterial checks it (body/material.h).
Material parseMaterial(const JsonObject& o, const Material& base = {});

// The body's orientation for an orientation of the file's axes: q_file E (mass/mass_model.h).
Quat toBodyOrientation(const BodyDef& def, const Quat& fileOrientation);

// The shapes described so far (issue 34), so that bodies of the same shape share one of each thing
// a shape costs: the mesh (and the file's), the collision shape with its hull, one mass-property
// computation, and one request to cook its grid or triangle hierarchy (rbsim/scene/cook.h). Two
// bodies share when their "shape" (a mesh file by its resolved path), "mass", "density", inertia
// method, "sdf" and "collide_as" are the same JSON; everything else (pose, material, fracture,
// scripts) stays per body. One cache lives for one load, or for the loads of one document that a
// compared phase makes (SceneCache), so a file edited between loads is read again.
class ShapeCache {
 public:
  struct Entry {
    BodyDef built;
    std::optional<CookRequest> request;  // what the shape needs cooked; none: nothing
    std::uint64_t listedIn = 0;          // the last scene whose Scene::cooking lists the request
  };
  // The entry an earlier parseBody built from the same shape keys, or null.
  Entry* find(const std::string& key);
  void add(const std::string& key, Entry entry);
  std::size_t size() const { return built_.size(); }
  // A new scene's description begins: each request is listed in its Scene::cooking once more.
  void beginScene() { ++scene_; }
  std::uint64_t scene() const { return scene_; }

 private:
  std::unordered_map<std::string, Entry> built_;
  std::uint64_t scene_ = 1;
};

// Appends the body described by `b` to scene.bodies (and its inertia method name), and to
// scene.cooking what its shape needs cooked. With `shapes`, a body whose shape keys match an
// earlier one's takes that body's shape instead of building it.
// Returns the body's "color", when it has one (a presentation key: the caller files it under the
// body's or the spawner's name in Scene::colors).
std::optional<Vec3> parseBody(const JsonObject& b, const std::string& baseDir, Scene& scene, ShapeCache* shapes = nullptr);
// One entry of a body's "forces", on body `index` whose file axes are `fileAxes`; without "end"
// it acts until `duration`.
ScriptedForce parseForce(const JsonObject& f, std::size_t index, const Mat3& fileAxes, double duration);
// Appends the forces, pose events and springs of body `index`.
void parseScripts(const JsonObject& b, std::size_t index, Scene& scene);
// The body named by o[key]; fails naming the field if there is none.
std::size_t findBody(const std::vector<BodyDef>& bodies, const JsonObject& o, const char* key);
// One plane: {"normal": [0, 1, 0], "point": [0, 0, 0], material keys}.
std::pair<Plane, Material> parsePlane(const JsonObject& p);
// "planes": [{...}, ...]
void parsePlanes(const JsonObject& root, Scene& scene);
// "spawn": [{"count", "seed", "name", "body": {...}, "region": {"min", "max"}, "speed": [lo, hi],
//            "angular_speed": [lo, hi]}, ...]
// Each block's template is parsed once (through `shapes`, when given) and its bodies copy it.
void parseSpawns(const JsonObject& root, const std::string& baseDir, Scene& scene, ShapeCache* shapes = nullptr);
// One spawn block; `spawnedVertices` counts the vertices of every block so far (a budget).
// Without "name", the block is named `defaultName`.
void parseSpawn(const JsonObject& s, const std::string& baseDir, Scene& scene, ShapeCache* shapes, double& spawnedVertices,
                const std::string& defaultName = "spawn");

}  // namespace rbsim::scene_detail
