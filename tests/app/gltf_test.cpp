// --gltf (app/export/): the file is read back with assimp, a reader that shares no code with the
// writer (tinygltf), and every body's pose at the first, a middle and the last frame is compared
// with the engine's own state at those frames, computed here by stepping the scene's World; a
// box's mesh is its 8 corners with flat faces; pieces broken off show exactly while they exist;
// the command line writes .glb and .gltf, the same file with or without images and from a replay,
// and refuses any other name.
#include <unistd.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include "shell_command.h"
#include "../sanitized_build.h"

#include "rbsim/scene/scene.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"
#include "run/phase.h"
#include "run/run_options.h"
#include "run/runner.h"

namespace rbsim::app {
namespace {

namespace fs = std::filesystem;

// A translation key is the engine's double rounded to float32: off by up to |x| 2^-24, so 1e-6 m
// holds for |x| < 16 m, and past that the float's own half step.
constexpr double kPositionTolerance = 1e-6;  // [m]
// A rotation key is q / |q| rounded to float32: each component off by 2^-24 and the norm by the
// engine's rounding; 1e-6 per component of the unit quaternion (after the sign of q is aligned:
// q and -q are one rotation).
constexpr double kQuaternionTolerance = 1e-6;  // [1]
// A key's time is k / fps in float32: off by its half step, under 1e-6 s for runs under 8 s.
constexpr double kTimeTolerance = 1e-6;  // [s]
// A normal is a unit cross product rounded to float32.
constexpr float kNormalTolerance = 1e-6f;  // [1]
// contact_response's bouncer is given 0.6 rad/s about z and tumbles as it bounces: at the end it
// must have turned by more than this, or the rotation check would compare identities.
constexpr double kMinTurn = 0.1;  // [rad]
// Under the sanitizers the two scenes run shorter (their whole 8 s and 7 s in the normal build):
// contact_response's bouncer turns 1.2 rad in 2 s at 0.6 rad/s, and fracture_wall's first wall
// breaks by step 90 of the 240 in 1 s.
const std::vector<std::string> kGltfPoseOverrides =
    test::kSanitizedBuild ? std::vector<std::string>{"world.duration=2"} : std::vector<std::string>{};
const std::vector<std::string> kGltfFractureOverrides =
    test::kSanitizedBuild ? std::vector<std::string>{"world.duration=1"} : std::vector<std::string>{};

fs::path tempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rbsim_gltf_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string scenePath(const std::string& name) { return std::string(RBSIM_ASSET_DIR) + "/scenes/" + name + ".json"; }

// Runs the phase without images into `out` (the library's path to --gltf --no-render).
void exportRun(const Phase& phase, const fs::path& out) {
  RunOptions options;
  options.render = false;
  options.quiet = true;
  options.gltfPath = out.string();
  runPhases({phase}, options, "");
}

const aiScene* readGltf(Assimp::Importer& importer, const fs::path& file) {
  // aiProcess_ValidateDataStructure: assimp's own consistency checks of what it read; no other
  // processing, so vertices, faces and keys stay as the file has them.
  return importer.ReadFile(file.string(), aiProcess_ValidateDataStructure);
}

// assimp's glTF 2 importer makes one aiNodeAnim per node, merging its translation, rotation and
// scale samplers, named as the node.
const aiNodeAnim* channelOf(const aiAnimation& animation, const std::string& node) {
  for (unsigned c = 0; c < animation.mNumChannels; ++c) {
    if (node == animation.mChannels[c]->mNodeName.C_Str()) return animation.mChannels[c];
  }
  return nullptr;
}

// Whether the node is shown at `frame`: a scale of 1, not 0 (glTF 2.0, 3.5.3: a zero scale hides a
// node). A body there all along has no scale sampler, and assimp 5.2 gives such a channel one
// scaling key, the node's own scale: 1.
bool shownAt(const aiNodeAnim& channel, std::uint64_t frame) {
  const aiVector3D& scale = channel.mScalingKeys[channel.mNumScalingKeys == 1 ? 0 : frame].mValue;
  EXPECT_TRUE(scale == aiVector3D(0.0f) || scale == aiVector3D(1.0f)) << channel.mNodeName.C_Str() << " frame " << frame;
  return scale == aiVector3D(1.0f);
}

// The frame a key stands for. assimp 5.2 keeps glTF's seconds in ticks of 1 ms
// (mTicksPerSecond 1000), so the time is rescaled here rather than assumed.
double keySeconds(const aiAnimation& animation, double ticks) {
  return ticks / (animation.mTicksPerSecond > 0.0 ? animation.mTicksPerSecond : 1.0);
}

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Gltf, EveryBodysPoseIsTheEnginesAtTheFirstAMiddleAndTheLastFrame) {
  const fs::path dir = tempDir("poses");
  const Phase phase = loadPhase(scenePath("contact_response"), kGltfPoseOverrides);
  const Scene& scene = phase.scene();
  exportRun(phase, dir / "run.glb");

  Assimp::Importer importer;
  const aiScene* read = readGltf(importer, dir / "run.glb");
  ASSERT_NE(read, nullptr) << importer.GetErrorString();
  ASSERT_EQ(read->mNumAnimations, 1u);
  const aiAnimation& animation = *read->mAnimations[0];
  EXPECT_EQ(animation.mNumChannels, scene.bodies.size());

  const std::uint64_t frames = frameCount(phase);
  const double fps = scene.view.fps;
  World world = buildWorld(scene);
  Quat startOfBouncer = Quat::Identity();
  for (const std::uint64_t frame : {std::uint64_t{0}, frames / 2, frames - 1}) {
    const std::uint64_t step = std::min(stepOfFrame(frame, fps, scene.settings.timeStep), scene.stepCount());
    while (world.stepCount() < step) world.step();
    ASSERT_EQ(world.bodies().size(), scene.bodies.size());
    for (const RigidBody& body : world.bodies()) {
      const aiNodeAnim* channel = channelOf(animation, body.name());
      ASSERT_NE(channel, nullptr) << body.name();
      ASSERT_EQ(channel->mNumPositionKeys, frames) << body.name();
      ASSERT_EQ(channel->mNumRotationKeys, frames) << body.name();
      EXPECT_EQ(channel->mNumScalingKeys, 1u) << body.name() << " is there all along: no visibility track";
      EXPECT_TRUE(shownAt(*channel, frame)) << body.name();
      const aiVectorKey& position = channel->mPositionKeys[frame];
      EXPECT_NEAR(keySeconds(animation, position.mTime), static_cast<double>(frame) / fps, kTimeTolerance) << body.name();
      const Vec3& x = body.position();
      for (int i = 0; i < 3; ++i) {
        const double tolerance = std::max(kPositionTolerance, std::abs(x[i]) * FLT_EPSILON);
        EXPECT_NEAR(position.mValue[i], x[i], tolerance) << body.name() << " frame " << frame << " x[" << i << "]";
      }
      // aiQuaternion is (w, x, y, z); glTF's keys are x, y, z, w: assimp reorders them.
      const aiQuaternion& r = channel->mRotationKeys[frame].mValue;
      const Quat& q = body.orientation();
      const double sign = r.w * q.w() + r.x * q.x() + r.y * q.y() + r.z * q.z() < 0.0 ? -1.0 : 1.0;
      EXPECT_NEAR(sign * r.w, q.w(), kQuaternionTolerance) << body.name() << " frame " << frame;
      EXPECT_NEAR(sign * r.x, q.x(), kQuaternionTolerance) << body.name() << " frame " << frame;
      EXPECT_NEAR(sign * r.y, q.y(), kQuaternionTolerance) << body.name() << " frame " << frame;
      EXPECT_NEAR(sign * r.z, q.z(), kQuaternionTolerance) << body.name() << " frame " << frame;
      if (body.name() == "bouncer") {
        if (frame == 0) startOfBouncer = q;
        if (frame == frames - 1) {
          EXPECT_GT(startOfBouncer.angularDistance(q), kMinTurn);
        }
      }
    }
  }
  fs::remove_all(dir);
}

TEST(Gltf, ABoxIsItsEightCornersWithFlatFacesInItsRenderColour) {
  const fs::path dir = tempDir("box");
  const Phase phase = loadPhase(scenePath("contact_response"), {"world.steps=1"});
  exportRun(phase, dir / "box.glb");
  Assimp::Importer importer;
  const aiScene* read = readGltf(importer, dir / "box.glb");
  ASSERT_NE(read, nullptr) << importer.GetErrorString();
  // Every body is a node of its own, named as in the scene, with one mesh.
  for (const BodyDef& body : phase.scene().bodies) {
    const aiNode* node = read->mRootNode->FindNode(body.name.c_str());
    ASSERT_NE(node, nullptr) << body.name;
    EXPECT_EQ(node->mNumMeshes, 1u) << body.name;
  }
  // The slider: "extents": [0.6, 0.3, 0.4], so corners at +-(0.3, 0.15, 0.2) about its centre of
  // mass; 6 faces of 2 triangles, each face's 4 corners with the face's own normal.
  const aiNode* slider = read->mRootNode->FindNode("slider");
  ASSERT_NE(slider, nullptr);
  const aiMesh& mesh = *read->mMeshes[slider->mMeshes[0]];
  EXPECT_EQ(mesh.mNumVertices, 24u);
  EXPECT_EQ(mesh.mNumFaces, 12u);
  ASSERT_TRUE(mesh.HasNormals());
  aiVector3D lo(1e9f), hi(-1e9f);
  std::set<std::tuple<float, float, float>> corners;
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    lo = aiVector3D(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
    hi = aiVector3D(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
    corners.insert({p.x, p.y, p.z});
    const aiVector3D& n = mesh.mNormals[v];
    EXPECT_NEAR(n.Length(), 1.0f, kNormalTolerance);
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, kNormalTolerance) << "a box face's normal is an axis";
  }
  EXPECT_EQ(corners.size(), 8u);
  const float half[3] = {0.3f, 0.15f, 0.2f};
  for (int i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(hi[i], half[i]);
    EXPECT_FLOAT_EQ(lo[i], -half[i]);
  }
  aiColor4D colour;
  ASSERT_EQ(read->mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_BASE_COLOR, colour), aiReturn_SUCCESS);
  EXPECT_FLOAT_EQ(colour.r, 0.9f);
  EXPECT_FLOAT_EQ(colour.g, 0.45f);
  EXPECT_FLOAT_EQ(colour.b, 0.25f);
  fs::remove_all(dir);
}

TEST(Gltf, PiecesBrokenOffShowExactlyWhileTheyExist) {
  const fs::path dir = tempDir("fracture");
  const Phase phase = loadPhase(scenePath("fracture_wall"), kGltfFractureOverrides);
  const Scene& scene = phase.scene();
  exportRun(phase, dir / "wall.glb");
  Assimp::Importer importer;
  const aiScene* read = readGltf(importer, dir / "wall.glb");
  ASSERT_NE(read, nullptr) << importer.GetErrorString();
  const aiAnimation& animation = *read->mAnimations[0];

  // Frame by frame, the engine's bodies by name against the nodes shown.
  const std::uint64_t frames = frameCount(phase);
  World world = buildWorld(scene);
  std::size_t switches = 0;
  for (std::uint64_t frame = 0; frame < frames; ++frame) {
    while (world.stepCount() < std::min(stepOfFrame(frame, scene.view.fps, scene.settings.timeStep), scene.stepCount())) {
      world.step();
    }
    std::multiset<std::string> engine, shown;
    for (const RigidBody& body : world.bodies()) engine.insert(body.name());
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
      const aiNodeAnim& channel = *animation.mChannels[c];
      ASSERT_TRUE(channel.mNumScalingKeys == 1 || channel.mNumScalingKeys == frames) << channel.mNodeName.C_Str();
      if (shownAt(channel, frame)) shown.insert(channel.mNodeName.C_Str());
      if (frame > 0 && shownAt(channel, frame) != shownAt(channel, frame - 1)) ++switches;
    }
    EXPECT_EQ(shown, engine) << "frame " << frame;
  }
  // Each break hides one node (the body, now its first piece, another mesh) and shows 1 + the
  // pieces added.
  std::size_t expected = 0;
  for (const FractureEvent& event : fractureEvents(world)) expected += 2 + event.added.size();
  EXPECT_GT(fractureEvents(world).size(), 0u) << "the wall must break for this test to test anything";
  EXPECT_EQ(switches, expected);
  fs::remove_all(dir);
}

// The real binary.
std::pair<int, std::string> rbsim(const std::vector<std::string>& args) {
  std::string command = test::shellQuote(RBSIM_BINARY);
  for (const std::string& a : args) command += " " + test::shellQuote(a);
  return test::runCommand(command + " 2>&1");
}

TEST(GltfCommand, RunWritesGlbAndGltfThatAssimpReadsWithTheSameKeys) {
  const fs::path dir = tempDir("cli");
  std::vector<std::vector<aiVectorKey>> keys;
  for (const char* name : {"run.glb", "run.gltf"}) {
    const auto [code, output] =
        rbsim({"run", "contact_response", "--no-render", "--steps", "240", "--gltf", (dir / name).string()});
    ASSERT_EQ(code, 0) << output;
    EXPECT_NE(output.find("gltf: " + (dir / name).string() + ", 5 bodies, 31 frames"), std::string::npos) << output;
    Assimp::Importer importer;
    const aiScene* read = readGltf(importer, dir / name);
    ASSERT_NE(read, nullptr) << name << ": " << importer.GetErrorString();
    ASSERT_EQ(read->mNumAnimations, 1u);
    const aiNodeAnim* bouncer = channelOf(*read->mAnimations[0], "bouncer");
    ASSERT_NE(bouncer, nullptr);
    keys.emplace_back(bouncer->mPositionKeys, bouncer->mPositionKeys + bouncer->mNumPositionKeys);
  }
  ASSERT_EQ(keys[0].size(), 31u);  // 240 steps of 1/240 s at 30 fps: frames 0 to 30
  for (std::size_t k = 0; k < keys[0].size(); ++k) EXPECT_TRUE(keys[0][k].mValue == keys[1][k].mValue) << k;
  fs::remove_all(dir);
}

TEST(GltfCommand, TheFileIsTheSameWithAVideoAndFromAReplay) {
  const fs::path dir = tempDir("same");
  const std::vector<std::string> run = {"run", "contact_response", "--steps", "24", "--quiet"};
  auto with = [&](std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return rbsim(args);
  };
  const fs::path alone = dir / "alone.glb", video = dir / "video.glb", replayed = dir / "replayed.glb";
  const std::string recording = (dir / "run.rbrec").string();
  auto [code, output] = with(run, {"--no-render", "--record", recording, "--gltf", alone.string()});
  ASSERT_EQ(code, 0) << output;
  std::tie(code, output) = with(run, {"--size", "64x48", "--video", (dir / "v.mp4").string(), "--gltf", video.string()});
  ASSERT_EQ(code, 0) << output;
  std::tie(code, output) = rbsim({"replay", recording, "--no-render", "--quiet", "--gltf", replayed.string()});
  ASSERT_EQ(code, 0) << output;
  EXPECT_TRUE(fs::exists(dir / "v.mp4"));
  const std::string bytes = readBytes(alone);
  EXPECT_GT(bytes.size(), 0u);
  EXPECT_TRUE(readBytes(video) == bytes) << "drawing frames must not change the poses written";
  EXPECT_TRUE(readBytes(replayed) == bytes) << "a replay must write what the run wrote";
  fs::remove_all(dir);
}

TEST(GltfCommand, AnotherExtensionExitsTwoNamingTheFlag) {
  const fs::path dir = tempDir("bad");
  const fs::path out = dir / "run.obj";
  const auto [code, output] = rbsim({"run", "contact_response", "--no-render", "--gltf", out.string()});
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find("--gltf " + out.string()), std::string::npos) << output;
  EXPECT_NE(output.find(".glb"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rbsim::app
