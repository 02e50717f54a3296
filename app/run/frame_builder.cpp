#include "run/frame_builder.h"

#include <cmath>
#include <cstdio>

#include "render/pane_layout.h"
#include "rbsim/math/rotation.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/systems.h"
#include "run/collision_view.h"
#include "run/particle_view.h"
#include "run/planar_view.h"
#include "run/sdf_slice_view.h"
#include "run/soft_view.h"
#include "run/to_glm.h"
#include "render/body_colors.h"

namespace rbsim::app {

namespace {

constexpr float kVertexDotPixels = 7.0f;  // a drawn world vertex (view.vertices), diameter [px]

}  // namespace

std::string formatVec(const Vec3& v, const char* unit) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%+9.4f %+9.4f %+9.4f %s", v.x(), v.y(), v.z(), unit);
  return buffer;
}

std::string formatNumber(double value, const char* unit) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g %s", value, unit);
  return buffer;
}

render::PanelMode panelMode(ViewDesc::Panel panel) {
  switch (panel) {
    case ViewDesc::Panel::Full: return render::PanelMode::Full;
    case ViewDesc::Panel::Off: return render::PanelMode::Off;
    case ViewDesc::Panel::Compact: break;
  }
  return render::PanelMode::Compact;
}

render::Camera sceneCamera(const ViewDesc& view) {
  render::Camera camera;
  camera.eye = toGlm(view.eye);
  camera.target = toGlm(view.target);
  camera.up = toGlm(view.up);
  camera.fovYDegrees = static_cast<float>(view.fovDegrees);
  return camera;
}

std::string freeFlightRow(const FreeFlightError& error, const World& world) {
  const FreeFlightError::Reading reading = error.read(world);
  if (!reading.tracked) {
    if (!world.isValid(error.body())) return "not compared (no body)";
    const RigidBody& body = world.body(error.body());
    return body.isStatic() ? "not compared (static)" : body.isKinematic() ? "not compared (kinematic)"
                                                          : "not compared (asleep)";
  }
  // An epoch at this very step: a contact, spring, joint or force turned it just now, and the
  // exact motion has not had a step to differ yet. Times are step counts times dt, so half a step
  // of slack tells this step from the last one whatever the rounding.
  constexpr double kThisStepSlack = 0.5;  // [steps]
  if (reading.since > world.time() - kThisStepSlack * world.settings().timeStep) {
    return "not compared (torqued this step)";
  }
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.3g rad, dE/E %+.2g, since %.3g s", reading.angle, reading.energy, reading.since);
  return buffer;
}

namespace {

// Joints as Box2D's b2DrawRevoluteJoint draws them: a segment from each body's centre of mass to
// its copy of the anchor, and for a hinge its axis through the anchor.
constexpr float kJointAxisHalfLength = 0.35f;  // [m] drawn each side of the anchor
const glm::vec3 kJointColor(1.0f, 0.8f, 0.1f);
const glm::vec3 kHingeAxisColor(0.2f, 1.0f, 0.9f);

void addJointLines(const World& world, render::FrameData& frame) {
  for (const Joint& joint : world.joints()) {
    const RigidBody& a = world.body(joint.def.bodyA);
    const Vec3 onA = a.bodyToWorld(joint.localAnchorMoving);
    frame.lines.push_back({toGlm(a.position()), toGlm(onA), kJointColor, true});
    if (joint.def.bodyB != kWorldAnchor) {
      const RigidBody& b = world.body(joint.def.bodyB);
      frame.lines.push_back({toGlm(b.position()), toGlm(b.bodyToWorld(joint.localAnchorBase)), kJointColor, true});
    }
    if (joint.def.type == JointDef::Type::Hinge) {
      const glm::vec3 axis = toGlm(a.rotation() * joint.localAxisMoving) * kJointAxisHalfLength;
      frame.lines.push_back({toGlm(onA) - axis, toGlm(onA) + axis, kHingeAxisColor, true});
    }
  }
}

}  // namespace

std::string restitutionThresholdRow(const World& world) {
  bool bouncy = false;
  for (std::size_t i = 0; i < world.bodies().size(); ++i) bouncy = bouncy || bodyMaterial(world, world.idAt(i)).restitution > 0.0;
  if (!bouncy) return {};
  const double threshold = world.settings().restitutionThreshold;
  if (threshold == 0.0) return "off: every approach bounces (seed 000's law)";
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.3g m/s approach: none", threshold);
  return buffer;
}

std::optional<render::PaneRect> scenePane(const ViewDesc& view) {
  const bool panel = view.overlay && view.panel != ViewDesc::Panel::Off;
  if (!panel && view.plots.empty()) return std::nullopt;
  return render::paneLayout(1, view.width, view.height, true, panelMode(view.panel)).front();
}

render::Camera viewCamera(const World& world, const ViewDesc& view) {
  render::Camera camera = sceneCamera(view);
  if (view.follow && view.selected < world.bodies().size()) {
    const glm::vec3 shift = toGlm(world.bodies()[view.selected].position()) - camera.target;
    camera.eye += shift;
    camera.target += shift;
  }
  return camera;
}

void placeBesidePanel(render::FrameData& frame, const ViewDesc& view) {
  const std::optional<render::PaneRect> rect = scenePane(view);
  if (!rect) return;
  render::FrameData pane;
  pane.bodies = std::move(frame.bodies);
  pane.forces = std::move(frame.forces);
  pane.lines = std::move(frame.lines);
  pane.points = std::move(frame.points);
  pane.sprites = std::move(frame.sprites);
  pane.options = frame.options;
  pane.camera = render::paneCamera(frame.camera, view.width, view.height, *rect);
  frame.panes.push_back(std::move(pane));
  frame.infoColumn = true;
  frame.overlay.plotsUnderPanel = true;
}

render::FrameData buildFrame(const World& world
, const Scene& scene, const std::string& demoTitle,
                             bool selectedBodyRows, const FreeFlightError* freeFlight) {
  render::FrameData frame;
  const ViewDesc& view = scene.view;
  frame.camera = viewCamera(world, view);
  frame.options.grid = view.grid;
  frame.options.wireframe = view.wireframe;
  frame.options.axes = view.axes;
  frame.options.overlay = view.overlay;

  const double t = world.time();
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const RigidBody& body = world.bodies()[i];
    render::BodyView bv;
    bv.worldVertices.reserve(body.vertexCount());
    for (const Vec3& p : body.worldVertices()) bv.worldVertices.push_back(toGlm(p));
    bv.triangles = &body.mesh().triangles;
    if (view.instancing) bv.mesh = body.sharedMesh();  // else drawn from worldVertices alone
    bv.position = toGlm(body.position());
    const Mat3& R = body.rotation();
    for (int c = 0; c < 3; ++c) bv.rotation[c] = toGlm(R.col(c));
    bv.color = toGlm(bodyColor(scene.colors, body.name()));
    const Vec3 extents = body.mesh().boundsMax() - body.mesh().boundsMin();
    bv.axisLength = static_cast<float>(0.75 * extents.maxCoeff());
    bv.selected = i == view.selected;
    if (view.vertices) {
      for (const glm::vec3& p : bv.worldVertices) frame.points.push_back({p, render::kDebugVertexColor, kVertexDotPixels});
    }
    frame.bodies.push_back(std::move(bv));
    for (const auto& [point, force] : activeForces(world, world.idAt(i), t)) {
      frame.forces.push_back({toGlm(point), toGlm(force)});
    }
  }

  render::OverlayData& overlay = frame.overlay;
  overlay.title = demoTitle.empty() ? scene.title : demoTitle;
  overlay.caption = view.caption;
  overlay.panel = panelMode(view.panel);
  using render::RowLevel;
  // In a scene of particles, soft bodies or 2D bodies the rigid bodies are the set, not the
  // subject: their rows are for the full panel.
  const bool rigidSubject = particleSystems(world).empty() && softBodies(world).empty() && planarWorld(world) == nullptr;
  const RowLevel rigid = rigidSubject ? RowLevel::Useful : RowLevel::Detail;
  overlay.rows = {{"time t", formatNumber(t, "s"), RowLevel::Essential}};
  if (!world.bodies().empty()) {
    overlay.rows.push_back({"integrator", std::string(integratorName(world.settings().integrator)) + ", dt " +
                                              formatNumber(world.settings().timeStep, "s"),
                            rigid});
  }
  if (const std::string threshold = restitutionThresholdRow(world); !threshold.empty()) {
    overlay.rows.push_back({"restitution below", threshold, RowLevel::Detail});
  }
  if (selectedBodyRows && view.selected < world.bodies().size()) {  // a scene of particles alone has no bodies
    const RigidBody& body = world.bodies()[view.selected];
    const Mat3& R = body.rotation();
    const Quat& q = body.orientation();
    char quat[96];
    std::snprintf(quat, sizeof quat, "%+.4f %+.4f %+.4f %+.4f", q.w(), q.x(), q.y(), q.z());
    // Yaw, pitch, roll about z, y', x'' (math/rotation.h), the scene's euler_zyx_deg.
    const Vec3 euler = eulerZyxFromRotation(R) * (180.0 / M_PI);
    char angles[96];
    std::snprintf(angles, sizeof angles, "%+.2f %+.2f %+.2f deg", euler.x(), euler.y(), euler.z());
    const RowLevel main = rigidSubject ? RowLevel::Essential : RowLevel::Detail;
    overlay.rows.insert(overlay.rows.end(), {
        // A body spawned while the World stepped has no inertia method in the scene's list.
        {"body", body.name() + " (" + (view.selected < scene.inertiaMethods.size() ? scene.inertiaMethods[view.selected] + " inertia, " : std::string()) +
                     formatNumber(body.mass(), "kg") + (body.awake() ? ")" : ", asleep)"), main},
        {"x", formatVec(body.position(), "m"), main},
        {"R row 1", formatVec(R.row(0).transpose(), ""), RowLevel::Detail},
        {"R row 2", formatVec(R.row(1).transpose(), ""), RowLevel::Detail},
        {"R row 3", formatVec(R.row(2).transpose(), ""), RowLevel::Detail},
        {"q (w x y z)", quat, RowLevel::Detail},
        {"Euler zyx", angles, RowLevel::Detail},
        {"v", formatVec(body.velocity(), "m/s"), rigid},
        {"omega", formatVec(body.angularVelocity(), "rad/s"), rigid},
        {"P", formatVec(body.state().linearMomentum, "kg m/s"), RowLevel::Detail},
        {"L", formatVec(body.state().angularMomentum, "kg m^2/s"), RowLevel::Detail},
        {"kinetic energy", formatNumber(body.kineticEnergy(), "J"), rigid},
    });
    if (freeFlight != nullptr) {
      // Kept whether or not the body flies free just now, so that the panel does not jump.
      overlay.rows.push_back({"vs exact spin", freeFlightRow(*freeFlight, world), main});
    }
  }
  if (!particleSystems(world).empty()) addParticleView(world, scene, frame);
  if (!softBodies(world).empty()) addSoftView(world, frame);
  if (planarWorld(world) != nullptr) addPlanarView(world, scene, frame);
  if (view.aabbs || view.contacts) addCollisionView(world, scene, frame);
  if (!world.joints().empty()) addJointLines(world, frame);
  if (view.sdfSlice) addSdfSliceView(world, scene, frame);
  return frame;
}

}  // namespace rbsim::app
