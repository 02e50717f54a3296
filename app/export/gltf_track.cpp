#include "export/gltf_track.h"

#include "rbsim/io/input_error.h"
#include "render/body_colors.h"

namespace rbsim::app {

namespace {

GltfPose poseOf(const RigidBody& body, const BodyTrack& track) {
  // glTF 2.0, 3.5.3: rotation is a unit quaternion. The engine's q is unit up to rounding; dividing
  // by its norm in double removes only that rounding before the cast to float.
  Quat q = body.orientation().normalized();
  // q and -q are one rotation. Appendix C.4's slerp takes the short way whatever the signs, but
  // implementations MAY approximate it (a componentwise lerp would swing the long way round), so
  // each key is put on the side of the previous one: every reading of a LINEAR track then agrees.
  if (!track.poses.empty()) {
    const std::array<float, 4>& p = track.poses.back().rotation;
    if (p[0] * q.x() + p[1] * q.y() + p[2] * q.z() + p[3] * q.w() < 0.0) q.coeffs() = -q.coeffs();
  }
  const Vec3& x = body.position();
  GltfPose pose;
  pose.translation = {static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z())};
  // Eigen's coeffs() are x, y, z, w: glTF's order; written out by name to say so.
  pose.rotation = {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()), static_cast<float>(q.w())};
  return pose;
}

}  // namespace

void GltfTrack::sample(const World& world, std::uint64_t frames) {
  std::map<Key, std::size_t> open;
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const RigidBody& body = world.bodies()[i];
    const BodyId id = world.idAt(i);
    const Key key{id.slot, id.generation, body.sharedMesh().get()};
    auto found = open_.find(key);
    std::size_t index = 0;
    if (found != open_.end()) {
      index = found->second;
    } else {
      index = tracks_.size();
      BodyTrack track;
      track.name = body.name().empty() ? "body " + std::to_string(i) : body.name();
      track.mesh = body.sharedMesh();
      track.color = bodyColor(colors_, body.name());
      track.firstFrame = frames_;
      tracks_.push_back(std::move(track));
    }
    BodyTrack& track = tracks_[index];
    track.poses.insert(track.poses.end(), frames, poseOf(body, track));
    open.emplace(key, index);
  }
  open_ = std::move(open);
  frames_ += frames;
}

void checkGltfScene(const Scene& scene) {
  const auto refuse = [&](const std::string& what) {
    throw InputError(scene.file, "--gltf", "the scene has " + what + ", which a glTF export does not hold: it writes rigid bodies alone");
  };
  if (!scene.particleSystems.empty()) refuse("particle systems");
  if (!scene.softBodies.empty()) refuse("soft bodies");
  if (scene.planar) refuse("a 2D world (planar)");
  if (!(scene.mostBodiesAtOnce() > 0.0)) throw InputError(scene.file, "--gltf", "the scene has no rigid bodies: a glTF export writes rigid bodies alone");
}

}  // namespace rbsim::app
