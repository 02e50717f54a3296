#include "export/gltf_mesh.h"

#include <array>
#include <cstring>
#include <map>

#include "render/frame_data.h"
#include "render/scene_geometry.h"

namespace rbsim::app {

GltfMeshArrays gltfMeshArrays(const Mesh& mesh) {
  // The body at the origin, unrotated: buildBodyShape's R^T (p' - x) gives back p, float for
  // float, so these are the renderer's own triangles and normals.
  render::BodyView body;
  body.triangles = &mesh.triangles;
  body.worldVertices.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) {
    body.worldVertices.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
  }
  std::vector<render::MeshVertex> triangles;
  std::vector<render::LineVertex> edges;  // outlines: the renderer's own, not a glTF primitive's
  render::buildBodyShape(body, triangles, edges);

  GltfMeshArrays out;
  // Keyed by the bits of position and normal: merges exact repeats only, never two corners that
  // are merely close.
  std::map<std::array<std::uint32_t, 6>, std::uint32_t> seen;
  for (const render::MeshVertex& v : triangles) {
    const std::array<float, 6> values{v.position.x, v.position.y, v.position.z, v.normal.x, v.normal.y, v.normal.z};
    std::array<std::uint32_t, 6> key{};
    std::memcpy(key.data(), values.data(), sizeof values);
    const auto [it, added] = seen.emplace(key, static_cast<std::uint32_t>(out.vertexCount()));
    if (added) {
      out.positions.insert(out.positions.end(), values.begin(), values.begin() + 3);
      out.normals.insert(out.normals.end(), values.begin() + 3, values.end());
    }
    out.indices.push_back(it->second);
  }
  return out;
}

}  // namespace rbsim::app
