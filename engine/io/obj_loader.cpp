#include "io/obj_loader.h"

#include <cmath>
#include <fstream>

#include <tiny_obj_loader.h>

#include "io/input_error.h"

namespace rbsim {

Mesh loadObj(const std::string& path) {
  if (!std::ifstream(path).good()) {
    throw InputError(path, "mesh", "cannot open the file (missing or unreadable)");
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    throw InputError(path, "mesh", "not a readable OBJ file: " + reader.Error());
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  Mesh mesh;
  mesh.name = path;
  const std::size_t vertexCount = attrib.vertices.size() / 3;
  mesh.vertices.reserve(vertexCount);
  for (std::size_t i = 0; i < vertexCount; ++i) {
    const Vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    if (!p.allFinite()) {
      throw InputError(path, "vertex " + std::to_string(i + 1), "coordinates must be finite numbers");
    }
    mesh.vertices.push_back(p);
  }
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      if (shape.mesh.num_face_vertices[f] != 3) {
        throw InputError(path, "shape '" + shape.name + "' face " + std::to_string(f + 1),
                         "expected a triangle after triangulation, got " +
                             std::to_string(shape.mesh.num_face_vertices[f]) + " vertices");
      }
      Triangle tri{};
      for (int k = 0; k < 3; ++k) {
        const int index = indices[3 * f + k].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertexCount) {
          throw InputError(path, "shape '" + shape.name + "' face " + std::to_string(f + 1),
                           "vertex index out of range");
        }
        tri[k] = static_cast<std::uint32_t>(index);
      }
      mesh.triangles.push_back(tri);
    }
  }
  if (mesh.vertices.empty() || mesh.triangles.empty()) {
    throw InputError(path, "mesh", "expected at least one triangle, the file has none");
  }
  return mesh;
}

}  // namespace rbsim
