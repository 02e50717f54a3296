#include "scene_blocks.h"

#include <filesystem>
#include <limits>

#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene_parts.h"
#include "render/checked_file.h"

namespace rbsim::python {

namespace {

// A force from Python without "end" acts for ever; in a file it would end with the scene's
// duration (docs/scene-format.md), so it is written with the largest end a double holds [s].
constexpr double kForeverEnd = std::numeric_limits<double>::max();

nlohmann::json vec3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

bool sameState(const BodyState& a, const BodyState& b) {
  return a.position == b.position && a.orientation.coeffs() == b.orientation.coeffs() &&
         a.linearMomentum == b.linearMomentum && a.angularMomentum == b.angularMomentum;
}

// A mesh file named relative to the working folder is written absolute: a scene file's relative
// names start at its own folder.
void absoluteMeshFile(nlohmann::json& shape) {
  if (!shape.is_object() || shape.value("type", nlohmann::json()) != "mesh" || !shape.contains("file")) return;
  if (!shape["file"].is_string()) return;
  const std::filesystem::path file = shape["file"].get<std::string>();
  if (file.is_relative()) shape["file"] = std::filesystem::absolute(file).lexically_normal().string();
}

void foreverForces(nlohmann::json& block) {
  if (!block.contains("forces") || !block["forces"].is_array()) return;
  for (nlohmann::json& f : block["forces"]) {
    if (f.is_object() && (!f.contains("end") || f["end"].is_null())) f["end"] = kForeverEnd;
  }
}

bool timedForce(const nlohmann::json& f) {
  return f.contains("end") || (f.contains("start") && !(f["start"].is_number() && f["start"].get<double>() == 0.0));
}

}  // namespace

void SceneBlocks::addBody(BodyId id, nlohmann::json block, const RigidBody& body) {
  if (block.contains("shape")) absoluteMeshFile(block["shape"]);
  if (block.contains("shapes") && block["shapes"].is_array()) {
    for (nlohmann::json& shape : block["shapes"]) absoluteMeshFile(shape);
  }
  bodies_[{id.slot, id.generation}] = Body{std::move(block), body.state()};
}

void SceneBlocks::addForce(BodyId id, nlohmann::json force) {
  nlohmann::json& block = bodies_.at({id.slot, id.generation}).block;
  if (!block.contains("forces") || block["forces"].is_null()) block["forces"] = nlohmann::json::array();
  block["forces"].push_back(std::move(force));
}

void SceneBlocks::addJoint(nlohmann::json block, const Joint& made) {
  joints_.push_back({std::move(block), {made.def.bodyA.slot, made.def.bodyA.generation},
                     {made.def.bodyB.slot, made.def.bodyB.generation}, made.def.name});
}

nlohmann::json SceneBlocks::bodyBlock(const RigidBody& body, const Body& kept) const {
  nlohmann::json block = kept.block;
  foreverForces(block);
  if (sameState(body.state(), kept.made)) return block;  // as given: read back bit for bit
  // Moved since (steps, set_pose, set_state): its pose now. The file's orientation is of the
  // file's axes, the body's of its principal axes (body_parser.cpp toBodyOrientation).
  block["position"] = vec3(body.position());
  const Mat3& axes = body.fileFrame().axes;
  const Quat q = axes == Mat3::Identity() ? body.orientation() : (body.orientation() * Quat(axes).conjugate()).normalized();
  block["orientation"] = {{"quaternion", {q.w(), q.x(), q.y(), q.z()}}};
  if (!body.isStatic()) {
    block["velocity"] = vec3(body.velocity());
    block["angular_velocity"] = vec3(body.angularVelocity());
  }
  return block;
}

nlohmann::json SceneBlocks::document(const World& world, const Scene& scene, const char* call) const {
  if (!loadedFrom_.empty()) {
    throw InputError(call, "", "this World was loaded from " + loadedFrom_ +
                                   ", which is its scene file; save_scene writes a World built with World() and add_body");
  }
  const bool timeRan = world.stepCount() > 0;
  const auto timed = [&](const std::string& what) {
    throw InputError(call, "", "the World has run " + std::to_string(world.stepCount()) + " steps and holds " + what +
                                   ", timed from its start, while a scene file's clock starts at 0; save it before the first step");
  };
  nlohmann::json doc = nlohmann::json::object();
  doc["title"] = scene.title;
  Scene settings = scene;
  settings.settings = world.settings();
  doc["world"] = worldBlockJson(settings);
  doc["bodies"] = nlohmann::json::array();
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const BodyId id = world.idAt(i);
    const RigidBody& body = world.bodies()[i];
    const auto kept = bodies_.find({id.slot, id.generation});
    if (kept == bodies_.end()) {
      throw InputError(call, "bodies", "body \"" + body.name() + "\" was made while the World stepped (by a spawner or a "
                                       "fracture); a scene file holds the bodies given to add_body only");
    }
    if (timeRan) {
      const nlohmann::json& b = kept->second.block;
      if (b.contains("set_pose") && !b["set_pose"].is_null()) timed("set_pose events (body \"" + body.name() + "\")");
      if (b.contains("motion") && !b["motion"].is_null()) timed("a kinematic motion (body \"" + body.name() + "\")");
      if (b.contains("forces") && b["forces"].is_array()) {
        for (const nlohmann::json& f : b["forces"]) {
          if (timedForce(f)) timed("a force with a start or an end (body \"" + body.name() + "\")");
        }
      }
    }
    doc["bodies"].push_back(bodyBlock(body, kept->second));
  }
  if (!planes_.empty()) doc["planes"] = planes_;
  if (!world.joints().empty()) {
    if (timeRan) timed("joints");
    // In the World's order (a removal may have reordered them), each by its bodies and name.
    std::vector<bool> used(joints_.size(), false);
    doc["joints"] = nlohmann::json::array();
    for (const Joint& joint : world.joints()) {
      const Key a{joint.def.bodyA.slot, joint.def.bodyA.generation}, b{joint.def.bodyB.slot, joint.def.bodyB.generation};
      std::size_t k = 0;
      while (k < joints_.size() && (used[k] || joints_[k].a != a || joints_[k].b != b || joints_[k].name != joint.def.name)) ++k;
      if (k == joints_.size()) throw InputError(call, "joints", "joint \"" + joint.def.name + "\" was made while the World stepped");
      used[k] = true;
      doc["joints"].push_back(joints_[k].block);
    }
  }
  if (!rbsim::spawners(world).empty()) {
    if (timeRan) timed("spawners");
    doc["spawn"] = spawners_;
  }
  if (!rbsim::killVolume(world).empty()) {
    doc["kill_volume"] = {{"min", vec3(rbsim::killVolume(world).min)}, {"max", vec3(rbsim::killVolume(world).max)}};
  }
  return doc;
}

void writeTextFile(const std::string& path, const std::string& text, const char* call) {
  render::CheckedFile out;
  if (!out.open(path) || !out.write(text) || !out.close()) {
    throw InputError(path, call, "cannot write the file (" + out.error() + ")");
  }
}

}  // namespace rbsim::python
