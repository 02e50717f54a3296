#include "io/obj_loader.h"

#include <algorithm>
#include <cmath>

#include <tiny_obj_loader.h>

#include "geometry/polygon_triangulation.h"
#include "rbsim/io/input_error.h"
#include "io/obj_prescan.h"
#include "io/read_file.h"

namespace rbsim {

namespace {

std::string faceField(const tinyobj::shape_t& shape, std::size_t face) {
  const std::string where = shape.name.empty() ? std::string() : "shape '" + shape.name + "' ";
  return where + "face " + std::to_string(face + 1);
}

}  // namespace

Mesh loadObj(const std::string& path) {
  return parseObj(readTextFile(path, kMaxObjFileBytes, "mesh", "an OBJ file"), path);
}

Mesh parseObj(const std::string& text, const std::string& path) {
  const ObjCounts counts = prescanObj(text, path);
  tinyobj::ObjReaderConfig config;
  // Polygons are triangulated below: tinyobjloader's own triangulation of faces with five or more
  // corners reads coordinates through indices it has not checked.
  config.triangulate = false;
  config.vertex_color = false;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  // Materials are never read: a mesh file's "mtllib" must not open other files.
  if (!reader.ParseFromString(text, "", config)) {
    throw InputError(path, "mesh", "not a readable OBJ file: " + reader.Error());
  }
  // tinyobjloader skips faces of one or two corners with only a warning; a skipped face would
  // leave a hole in the mesh without a word.
  if (reader.Warning().find("Degenerated face") != std::string::npos) {
    throw InputError(path, "mesh", "a face has fewer than 3 vertices (an 'f' line needs at least 3 indices)");
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  Mesh mesh;
  mesh.name = path;
  const std::size_t vertexCount = attrib.vertices.size() / 3;
  mesh.vertices.reserve(vertexCount);
  mesh.triangles.reserve(counts.triangles);
  for (std::size_t i = 0; i < vertexCount; ++i) {
    const Vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    if (!p.allFinite()) {
      throw InputError(path, "vertex " + std::to_string(i + 1), "coordinates must be finite numbers");
    }
    mesh.vertices.push_back(p);
  }
  std::vector<std::uint32_t> corners;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t next = 0;  // first index of the current face in shape.mesh.indices
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t count = shape.mesh.num_face_vertices[f];
      if (count < 3 || count > std::min(kMaxObjFaceCorners, kMaxPolygonCorners)) {  // prescanObj refused these
        throw InputError(path, faceField(shape, f), "has " + std::to_string(count) + " corners; expected 3 to " +
                         std::to_string(std::min(kMaxObjFaceCorners, kMaxPolygonCorners)));
      }
      corners.clear();
      for (std::size_t k = 0; k < count; ++k) {
        const int index = shape.mesh.indices[next + k].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertexCount) {
          throw InputError(path, faceField(shape, f), "vertex index out of range (the file has " +
                           std::to_string(vertexCount) + " vertices)");
        }
        corners.push_back(static_cast<std::uint32_t>(index));
      }
      next += count;
      if (!triangulatePolygon(mesh.vertices, corners, mesh.triangles)) {
        if (count == 3) {
          mesh.triangles.push_back({corners[0], corners[1], corners[2]});  // checkMesh counts it
          continue;
        }
        throw InputError(path, faceField(shape, f), "a polygon of " + std::to_string(count) +
                         " corners that cannot be triangulated: it has no area or crosses itself");
      }
    }
  }
  if (mesh.triangles.empty()) {
    throw InputError(path, "mesh", "no faces ('f' lines) among " + std::to_string(vertexCount) +
                     " vertices: an empty file, or not an OBJ mesh");
  }
  return mesh;
}

}  // namespace rbsim
