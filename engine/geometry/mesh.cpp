#include "geometry/mesh.h"

#include <limits>
#include <map>
#include <utility>

namespace rbsim {

Vec3 Mesh::boundsMin() const {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  for (const Vec3& p : vertices) lo = lo.cwiseMin(p);
  return lo;
}

Vec3 Mesh::boundsMax() const {
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  for (const Vec3& p : vertices) hi = hi.cwiseMax(p);
  return hi;
}

Mesh makeBox(const Vec3& extents) {
  const Vec3 h = 0.5 * extents;
  Mesh box;
  box.name = "box";
  // Seed 004's vertex order p0..p7: bottom face (z = -h) counter-clockwise, then top face.
  box.vertices = {{-h.x(), -h.y(), -h.z()}, {+h.x(), -h.y(), -h.z()},
                  {+h.x(), +h.y(), -h.z()}, {-h.x(), +h.y(), -h.z()},
                  {-h.x(), -h.y(), +h.z()}, {+h.x(), -h.y(), +h.z()},
                  {+h.x(), +h.y(), +h.z()}, {-h.x(), +h.y(), +h.z()}};
  box.triangles = {{0, 2, 1}, {0, 3, 2},   // -z
                   {4, 5, 6}, {4, 6, 7},   // +z
                   {0, 1, 5}, {0, 5, 4},   // -y
                   {3, 7, 6}, {3, 6, 2},   // +y
                   {0, 4, 7}, {0, 7, 3},   // -x
                   {1, 2, 6}, {1, 6, 5}};  // +x
  return box;
}

MeshCheck checkMesh(const Mesh& mesh) {
  MeshCheck check;
  // Directed edge -> how many triangles traverse it in that direction.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (std::uint32_t idx : tri) {
      if (idx >= mesh.vertices.size()) {
        check.problem = "triangle " + std::to_string(t) + " indexes vertex " + std::to_string(idx) +
                        " but the mesh has " + std::to_string(mesh.vertices.size());
        return check;
      }
    }
    const Vec3& a = mesh.vertices[tri[0]];
    const Vec3& b = mesh.vertices[tri[1]];
    const Vec3& c = mesh.vertices[tri[2]];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || (b - a).cross(c - a).norm() == 0.0) {
      ++check.degenerateTriangles;
    }
    for (int e = 0; e < 3; ++e) ++directed[{tri[e], tri[(e + 1) % 3]}];
  }
  check.closed = true;
  check.consistentlyOriented = true;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    const int reverseCount = reverse == directed.end() ? 0 : reverse->second;
    if (count + reverseCount != 2) {
      check.closed = false;
      if (check.problem.empty()) {
        check.problem = "edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
                        ") is used by " + std::to_string(count + reverseCount) +
                        " triangles; a closed surface uses every edge exactly twice";
      }
    } else if (count != 1) {
      check.consistentlyOriented = false;
      if (check.problem.empty()) {
        check.problem = "edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
                        ") is traversed twice in the same direction: inconsistent winding";
      }
    }
  }
  if (check.problem.empty() && check.degenerateTriangles > 0) {
    check.problem = std::to_string(check.degenerateTriangles) + " degenerate (zero-area) triangles";
  }
  if (mesh.triangles.empty()) {
    check.closed = false;
    check.problem = "the mesh has no triangles";
  }
  return check;
}

void translateMesh(Mesh& mesh, const Vec3& offset) {
  for (Vec3& p : mesh.vertices) p -= offset;
}

}  // namespace rbsim
