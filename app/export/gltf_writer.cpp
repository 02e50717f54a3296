#include "export/gltf_writer.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include "export/gltf_mesh.h"

namespace rbsim::app {

namespace {

// glTF 2.0, 3.6.2.4 "Data Alignment": an accessor starts at a multiple of its component's size,
// and a vertex attribute at a multiple of 4 bytes; every view here starts at a multiple of 4.
constexpr std::size_t kViewAlignment = 4;  // [bytes]

// Fills the model's one buffer, a view and an accessor at a time.
class ModelBuilder {
 public:
  explicit ModelBuilder(tinygltf::Model& model) : model_(model) {
    model_.buffers.emplace_back();  // 3.6.1.2: in a .glb, buffer 0 without a uri is the BIN chunk
  }

  // An accessor of `values`, `components` of them per element of `type` (TINYGLTF_TYPE_VEC3 ...),
  // tightly packed in a view of its own. `target` is the view's (0: animation
  // data, for which 3.6.1.1 names no target). With `bounds`, min and max per component: 3.6.2.5 asks
  // them of POSITION and of an animation's input.
  template <typename T>
  int accessor(const std::vector<T>& values, int componentType, int type, int components, int target, bool bounds) {
    std::vector<unsigned char>& data = model_.buffers.front().data;
    data.resize((data.size() + kViewAlignment - 1) / kViewAlignment * kViewAlignment, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    data.resize(data.size() + view.byteLength);
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);  // little-endian, as 3.6.1.1 asks
    model_.bufferViews.push_back(view);

    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = values.size() / static_cast<std::size_t>(components);
    if (bounds) {
      accessor.minValues.assign(components, std::numeric_limits<double>::infinity());
      accessor.maxValues.assign(components, -std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % static_cast<std::size_t>(components);
        accessor.minValues[c] = std::min(accessor.minValues[c], static_cast<double>(values[i]));
        accessor.maxValues[c] = std::max(accessor.maxValues[c], static_cast<double>(values[i]));
      }
    }
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  int floats(const std::vector<float>& values, int type, int components, int target = 0, bool bounds = false) {
    return accessor(values, TINYGLTF_COMPONENT_TYPE_FLOAT, type, components, target, bounds);
  }

 private:
  tinygltf::Model& model_;
};

// The accessors of one engine mesh, shared by every glTF mesh drawn with it (3.7.2.1).
struct MeshAccessors {
  int position = -1, normal = -1, indices = -1;  // -1: a mesh with no triangles, drawn as nothing
};

MeshAccessors meshAccessors(const Mesh& mesh, ModelBuilder& builder) {
  const GltfMeshArrays arrays = gltfMeshArrays(mesh);
  MeshAccessors out;
  if (arrays.indices.empty()) return out;  // an accessor of 0 elements is invalid (count >= 1)
  out.position = builder.floats(arrays.positions, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  out.normal = builder.floats(arrays.normals, TINYGLTF_TYPE_VEC3, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
  out.indices = builder.accessor(arrays.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, 1,
                                 TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, false);
  return out;
}

// The body's render colour as a material (3.9.2: baseColorFactor is linear RGBA, as the colour).
tinygltf::Material material(const Vec3& color) {
  tinygltf::Material m;
  std::ostringstream name;
  name << "colour " << color.x() << " " << color.y() << " " << color.z();
  m.name = name.str();
  m.pbrMetallicRoughness.baseColorFactor = {color.x(), color.y(), color.z(), 1.0};
  m.pbrMetallicRoughness.metallicFactor = kGltfMetallic;
  m.pbrMetallicRoughness.roughnessFactor = kGltfRoughness;
  // The renderer lights both sides (a mesh file wound inwards still shows from outside); 3.9.5 "Double Sided".
  m.doubleSided = true;
  return m;
}

// A track's pose at every frame of the run: before it appears its first pose, after it is gone
// its last (it is hidden then, see `visible`).
GltfPose poseAt(const BodyTrack& track, std::uint64_t frame) {
  if (frame < track.firstFrame) return track.poses.front();
  return frame < track.endFrame() ? track.poses[frame - track.firstFrame] : track.poses.back();
}

bool visible(const BodyTrack& track, std::uint64_t frame) { return frame >= track.firstFrame && frame < track.endFrame(); }

void addChannel(tinygltf::Animation& animation, int node, const char* path, int input, int output, const char* interpolation) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = interpolation;
  animation.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(channel);
}

}  // namespace

tinygltf::Model buildGltfModel(const GltfTrack& track, double fps, const std::string& title) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = std::string("rbsim ") + RBSIM_VERSION;
  ModelBuilder builder(model);
  const std::uint64_t frames = track.frames();

  std::map<const Mesh*, MeshAccessors> shapes;
  std::map<std::pair<const Mesh*, int>, int> meshes;  // (shape, material) -> glTF mesh
  std::map<std::array<double, 3>, int> materials;     // colour -> material
  tinygltf::Scene scene;
  scene.name = title;
  for (const BodyTrack& body : track.bodies()) {
    auto shape = shapes.find(body.mesh.get());
    if (shape == shapes.end()) shape = shapes.emplace(body.mesh.get(), meshAccessors(*body.mesh, builder)).first;
    const std::array<double, 3> colour{body.color.x(), body.color.y(), body.color.z()};
    auto mat = materials.find(colour);
    if (mat == materials.end()) {
      model.materials.push_back(material(body.color));
      mat = materials.emplace(colour, static_cast<int>(model.materials.size()) - 1).first;
    }
    tinygltf::Node node;
    node.name = body.name;
    if (shape->second.indices >= 0) {
      auto mesh = meshes.find({body.mesh.get(), mat->second});
      if (mesh == meshes.end()) {
        tinygltf::Primitive primitive;  // 3.7.2.1: mode defaults to triangles
        primitive.attributes["POSITION"] = shape->second.position;
        primitive.attributes["NORMAL"] = shape->second.normal;
        primitive.indices = shape->second.indices;
        primitive.material = mat->second;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh m;
        // "box", "wall/3" (a piece), or a mesh file's name without the folders of this machine
        const std::filesystem::path name(body.mesh->name);
        m.name = name.is_absolute() ? name.filename().string() : body.mesh->name;
        m.primitives.push_back(primitive);
        model.meshes.push_back(m);
        mesh = meshes.emplace(std::make_pair(body.mesh.get(), mat->second), static_cast<int>(model.meshes.size()) - 1).first;
      }
      node.mesh = mesh->second;
    }
    // The pose at time 0, for a viewer that does not play the animation.
    const GltfPose first = poseAt(body, 0);
    node.translation.assign(first.translation.begin(), first.translation.end());
    node.rotation.assign(first.rotation.begin(), first.rotation.end());
    if (!visible(body, 0)) node.scale = {0.0, 0.0, 0.0};
    scene.nodes.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(node);
  }
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  // 3.11 "Animations": one input (the frame times, in seconds) shared by every sampler.
  std::vector<float> times(frames);
  for (std::uint64_t k = 0; k < frames; ++k) times[k] = static_cast<float>(static_cast<double>(k) / fps);
  const int input = builder.floats(times, TINYGLTF_TYPE_SCALAR, 1, 0, true);
  tinygltf::Animation animation;
  animation.name = title;
  std::vector<float> translations, rotations, scales;
  for (std::size_t n = 0; n < track.bodies().size(); ++n) {
    const BodyTrack& body = track.bodies()[n];
    translations.clear();
    rotations.clear();
    for (std::uint64_t k = 0; k < frames; ++k) {
      const GltfPose pose = poseAt(body, k);
      translations.insert(translations.end(), pose.translation.begin(), pose.translation.end());
      rotations.insert(rotations.end(), pose.rotation.begin(), pose.rotation.end());
    }
    const int node = static_cast<int>(n);
    addChannel(animation, node, "translation", input, builder.floats(translations, TINYGLTF_TYPE_VEC3, 3), "LINEAR");
    addChannel(animation, node, "rotation", input, builder.floats(rotations, TINYGLTF_TYPE_VEC4, 4), "LINEAR");
    if (body.firstFrame == 0 && body.endFrame() == frames) continue;
    // A body there for part of the run (a fracture piece, a body that broke): 3.5.3 lets a scale
    // of zero on all three axes hide a node, and STEP holds each key until the next, so it shows
    // from its first frame to its last and not a moment before or after.
    scales.clear();
    for (std::uint64_t k = 0; k < frames; ++k) scales.insert(scales.end(), 3, visible(body, k) ? 1.0f : 0.0f);
    addChannel(animation, node, "scale", input, builder.floats(scales, TINYGLTF_TYPE_VEC3, 3), "STEP");
  }
  model.animations.push_back(animation);
  return model;
}

}  // namespace rbsim::app
