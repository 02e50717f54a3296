#pragma once
// A scene file (JSON) parsed into plain engine data. The format is documented in
// docs/scene-format.md; every error names the file, the JSON path and what was expected.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbsim/body/body_def.h"
#include "rbsim/shapes/plane.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/planar/planar_world.h"
#include "rbsim/soft/soft_body.h"
#include "rbsim/world/scripts.h"
#include "rbsim/world/spring.h"
#include "rbsim/settings/settings.h"
#include "rbsim/world/ragdoll.h"
#include "rbsim/world/world.h"
#include "rbsim/scene/cook.h"
#include "rbsim/scene/view_desc.h"

namespace rbsim {

// A Scene names its bodies (in forces, pose events, springs and joints) by the ids that
// buildWorld's World gives them: a fresh World numbers bodies added in order by slot, generation
// 0, so body i of Scene::bodies gets sceneBodyId(i) (buildWorld checks it).
inline BodyId sceneBodyId(std::size_t index) { return {static_cast<std::uint32_t>(index), 0}; }

struct Scene {
  std::string file;        // where it came from, for messages
  std::vector<std::string> files;  // every other file it read (meshes), as opened
  std::string title;
  Settings settings;
  // world.threads was given (in the file or by --set). Without it a run that renders gives the
  // physics one thread (app/run/runner.cpp): the rasteriser and the encoder use every core.
  bool threadsGiven = false;
  double duration = 5.0;   // simulated time to run [s]
  std::vector<BodyDef> bodies;
  std::vector<std::string> inertiaMethods;  // per body, as resolved ("cube" or "exact")
  std::vector<ScriptedForce> forces;
  std::vector<PoseEvent> poseEvents;
  std::vector<Spring> springs;
  std::vector<KinematicMotion> motions;  // kinematic bodies' prescribed motions
  std::vector<SpawnerDef> spawners;      // "spawn" blocks with a "period": bodies added while stepping
  Aabb killVolume;                       // "kill_volume"; empty: none
  std::vector<RagdollDef> ragdolls;      // "ragdolls": presets added after the joints
  std::vector<JointDef> joints;  // ball and hinge joints (dynamics/joint.h)
  std::vector<Plane> planes;  // static, infinite
  std::vector<Material> planeMaterials;  // per plane
  // world.particle_integrator: the integrator of particle systems that do not name their own, as
  // world.integrator is for bodies.
  ParticleIntegrator particleIntegrator = ParticleIntegrator::SemiImplicitEuler;
  std::vector<ParticleSystemDef> particleSystems;
  std::vector<ParticleLook> particleLooks;  // per particle system
  std::vector<SoftBodyDef> softBodies;      // FEM soft bodies (engine/soft)
  std::optional<PlanarWorld> planar;        // a 2D world in the xy plane (engine/planar)
  std::vector<Vec3> planarColors;           // per 2D body, linear RGB
  double planarDepth = 0.4;                 // [m] the 2D bodies are drawn as prisms this thick
  ViewDesc view;
  BodyColors colors;  // how the bodies are drawn: the World never sees it
  // What the shapes of the bodies and spawner prototypes still need built for collision, one
  // request per distinct shape (cook.h); cookScene empties it. buildWorld takes a cooked scene.
  std::vector<CookRequest> cooking;

  std::uint64_t stepCount() const;  // steps covering `duration` at settings.timeStep
  // The most bodies the scene's World holds at once over `duration`: the listed ones, every
  // ragdoll's bones and what the spawners' bursts add, less what their lifetimes have removed
  // (issue 56, item 1: the budgets of outputs count everything the scene will make). A double:
  // an estimate no product can wrap. The kill volume is not counted: it may remove nothing.
  double mostBodiesAtOnce() const;
};

// Reads and parses a scene file; `overrides` are "path=value" assignments (the --set flag)
// applied to the JSON before it is checked. Throws InputError.
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for the text of a scene file; `file` names it in messages.
Scene parseSceneText(const std::string& text, const std::string& file, const std::string& baseDir,
                     const std::vector<std::string>& overrides = {});

// Parses an in-memory document and cooks it (cook.h); mesh paths are relative to `baseDir`.
Scene parseScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir);

// The parser alone: the document as a plain description, every key checked, meshes read and mass
// properties computed, but no grid or triangle hierarchy built (Scene::cooking lists them for
// cookScene). With `cache`, shapes described by an earlier call through it are reused.
Scene describeScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir,
                    SceneCache* cache = nullptr);

// The text of a scene file as a JSON document (strict: no duplicate keys, bounded depth) with the
// "path=value" `overrides` applied; an error names the file and the --set assignment.
nlohmann::json readSceneDocument(const std::string& text, const std::string& file,
                                 const std::vector<std::string>& overrides = {});

// "bodies[1].shape.extents" and "bodies.1.shape.extents" both give {bodies, 1, shape, extents}:
// the parts of a --set path.
std::vector<std::string> splitScenePath(const std::string& path);

// The text of a scene file. Throws InputError naming it when it is a folder or cannot be read.
std::string readSceneFile(const std::string& path);

// Applies one "a.b[2].c=value" (or "a.b.2.c=value") assignment; the value is JSON if it parses
// as JSON, otherwise a string. Bodies may be named: "bodies.box.mass=2".
void applyOverride(nlohmann::json& document, const std::string& assignment);

// A World holding the scene's bodies, forces, pose events, planes and particle systems. The scene
// must be cooked (Scene::cooking empty): std::logic_error otherwise.
World buildWorld(const Scene& scene);

}  // namespace rbsim
