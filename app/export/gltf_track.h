#pragma once
// A run's motion for a glTF animation (gltf_writer.h): every body's pose at every frame time, the
// frames the video draws (frame k, at k / view.fps, shows the step nearest to it: runner.h
// stepOfFrame). A body is followed by its id and its mesh together: a body that breaks keeps its
// id but becomes its first piece, another mesh (engine fracture/fracture.h), so from then on it is
// another track, as are the pieces added beside it; a body destroyed ends its track.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// One pose in glTF's float32 and order (glTF 2.0, 3.5.3 "Transformations": translation XYZ,
// rotation a unit quaternion XYZW): the node moves a mesh vertex p of the body frame to R p + x,
// the engine's p' = R p + x, since the mesh is in the body frame about the centre of mass.
struct GltfPose {
  std::array<float, 3> translation{};  // x [m]
  std::array<float, 4> rotation{};     // q as x, y, z, w
};

// The poses of one body (or one piece) over the frames it was in the world.
struct BodyTrack {
  std::string name;                  // the body's name in the scene; "body N" if it has none
  std::shared_ptr<const Mesh> mesh;  // body frame [m]
  Vec3 color = Vec3::Ones();         // the render colour, linear RGB
  std::uint64_t firstFrame = 0;      // the frame it first appears in
  std::vector<GltfPose> poses;       // frames firstFrame .. firstFrame + poses.size() - 1
  std::uint64_t endFrame() const { return firstFrame + poses.size(); }
};

class GltfTrack {
 public:
  // The bodies are drawn in `colors` (the scene's, render/body_colors.h).
  explicit GltfTrack(BodyColors colors = {}) : colors_(std::move(colors)) {}
  // Appends the world's bodies as the next `frames` frames (a run without images steps from one
  // frame at which a body moves on to the next: the frames between show this same state).
  void sample(const World& world, std::uint64_t frames = 1);
  std::uint64_t frames() const { return frames_; }
  // In the order the bodies first appeared (the scene's order, then pieces as they broke off).
  const std::vector<BodyTrack>& bodies() const { return tracks_; }

 private:
  BodyColors colors_;
  using Key = std::tuple<std::uint32_t, std::uint32_t, const Mesh*>;  // id's slot, generation; mesh
  std::vector<BodyTrack> tracks_;
  std::map<Key, std::size_t> open_;  // the tracks of the bodies of the last sample
  std::uint64_t frames_ = 0;
};

// Throws InputError (the scene's file, field --gltf) unless the scene is one that a track holds:
// at least one rigid body, and no particles, soft bodies or 2D world, which are not rigid bodies
// and have no node to move. (One phase of one world is the runner's to check.)
void checkGltfScene(const Scene& scene);

}  // namespace rbsim::app
