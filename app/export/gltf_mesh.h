#pragma once
// A body's mesh as the arrays of a glTF mesh primitive: the triangles the renderer draws for it,
// flat shaded, in the body frame (render/scene_geometry.h buildBodyShape, which instanced drawing
// uses too), with the corners that share a position and a normal merged, so that each flat face
// keeps its own normals while its triangles share their corners through the indices.
#include <cstdint>
#include <vector>

#include "rbsim/geometry/mesh.h"

namespace rbsim::app {

struct GltfMeshArrays {
  std::vector<float> positions;        // x, y, z per vertex, body frame [m]
  std::vector<float> normals;          // unit x, y, z per vertex
  std::vector<std::uint32_t> indices;  // 3 per triangle, counter-clockwise seen from outside
  std::size_t vertexCount() const { return positions.size() / 3; }
};

// The mesh's triangles as drawn; a triangle whose indices leave the vertex list is skipped, as
// the renderer skips it.
GltfMeshArrays gltfMeshArrays(const Mesh& mesh);

}  // namespace rbsim::app
