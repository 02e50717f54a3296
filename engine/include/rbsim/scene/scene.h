#pragma once
// A scene file (JSON) parsed into plain engine data. The format is documented in README.md
// ("Scene format"); every error names the file, the JSON path and what was expected.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbsim/body/body_def.h"
#include "rbsim/collision/contact.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/planar/planar_world.h"
#include "rbsim/soft/soft_body.h"
#include "rbsim/world/scripts.h"
#include "rbsim/world/spring.h"
#include "rbsim/settings/settings.h"
#include "rbsim/world/world.h"

namespace rbsim {

// How the scene is shown; plain data, the app turns it into pixels.
struct ViewDesc {
  Vec3 eye = Vec3(4.0, 3.0, 6.0);      // camera position [m]
  Vec3 target = Vec3(0.0, 0.5, 0.0);   // point looked at [m]
  Vec3 up = Vec3(0.0, 1.0, 0.0);
  double fovDegrees = 45.0;            // vertical field of view
  int width = 1280;                    // [px]
  int height = 720;                    // [px]
  int fps = 30;                        // frames per simulated second
  bool overlay = true;
  bool wireframe = false;
  bool axes = true;
  bool grid = true;
  bool aabbs = false;     // draw AABBs (red when in a pair), compare pairs with brute force
  bool contacts = false;  // draw contact points, normals, distances and impact ghosts
  // Draw each body's vertex list p' = R p + x as the engine computed it (seed 004 section 2: "do
  // this transform yourself"), as dots over the body the renderer drew from R and x.
  bool vertices = false;
  std::size_t selected = 0;            // body shown in the overlay
  std::string caption;
  // Time plots in the overlay (app/run/plot_history.h): names of kPlotQuantities, of the whole
  // scene or (plotSelected) of the selected body, over the last plotSeconds.
  std::vector<std::string> plots;
  bool plotSelected = false;
  double plotSeconds = 10.0;  // [s]
};

// The quantities view.plots may name.
inline const std::vector<std::string> kPlotQuantities = {"ke", "pe", "E", "|P|", "|L|", "contacts", "error"};

// How one particle system is drawn: camera-facing sprites whose colour, opacity and size follow
// the particle's age fraction a = age / lifetime from birth (a = 0) to death (a = 1).
struct ParticleLook {
  enum class Blend { Additive, Alpha };
  Blend blend = Blend::Alpha;        // additive: light adds up (fire); alpha: covers (smoke)
  bool hasColorEnd = false;          // false: the birth colour throughout
  Vec3 colorEnd = Vec3::Zero();      // linear RGB at a = 1, mixed linearly from the birth colour
  double alphaStart = 1.0;           // opacity at a = 0 [1]
  double alphaEnd = 1.0;             // opacity at a = 1 [1]
  double sizeEndScale = 1.0;         // drawn size at a = 1 over the size at birth [1]
};

// A Scene names its bodies (in forces, pose events, springs and joints) by the ids that
// buildWorld's World gives them: a fresh World numbers bodies added in order by slot, generation
// 0, so body i of Scene::bodies gets sceneBodyId(i) (buildWorld checks it).
inline BodyId sceneBodyId(std::size_t index) { return {static_cast<std::uint32_t>(index), 0}; }

struct Scene {
  std::string file;        // where it came from, for messages
  std::string title;
  Settings settings;
  double duration = 5.0;   // simulated time to run [s]
  std::vector<BodyDef> bodies;
  std::vector<std::string> inertiaMethods;  // per body, as resolved ("cube" or "exact")
  std::vector<ScriptedForce> forces;
  std::vector<PoseEvent> poseEvents;
  std::vector<Spring> springs;
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

  std::uint64_t stepCount() const;  // steps covering `duration` at settings.timeStep
};

// Reads and parses a scene file; `overrides` are "path=value" assignments (the --set flag)
// applied to the JSON before it is checked. Throws InputError.
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for the text of a scene file; `file` names it in messages.
Scene parseSceneText(const std::string& text, const std::string& file, const std::string& baseDir,
                     const std::vector<std::string>& overrides = {});

// Parses an in-memory document; mesh paths are relative to `baseDir`.
Scene parseScene(const nlohmann::json& document, const std::string& file, const std::string& baseDir);

// "bodies[1].shape.extents" and "bodies.1.shape.extents" both give {bodies, 1, shape, extents}:
// the parts of a --set path.
std::vector<std::string> splitScenePath(const std::string& path);

// The text of a scene file. Throws InputError naming it when it is a folder or cannot be read.
std::string readSceneFile(const std::string& path);

// Applies one "a.b[2].c=value" (or "a.b.2.c=value") assignment; the value is JSON if it parses
// as JSON, otherwise a string. Bodies may be named: "bodies.box.mass=2".
void applyOverride(nlohmann::json& document, const std::string& assignment);

// A World holding the scene's bodies, forces, pose events, planes and particle systems.
World buildWorld(const Scene& scene);

}  // namespace rbsim
