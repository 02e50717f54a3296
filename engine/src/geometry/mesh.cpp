#include "rbsim/geometry/mesh.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
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

double convexityTolerance(const Mesh& mesh) {
  if (mesh.vertices.empty()) return 0.0;
  const Vec3 lo = mesh.boundsMin(), hi = mesh.boundsMax();
  const double magnitude = lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).sum();  // sum_i max |p_i| [m]
  return std::max(kConvexRelativeTolerance * (hi - lo).norm(), kConvexFloatTolerance * FLT_EPSILON * magnitude);
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

namespace rbsim {

namespace {

struct FacePlane {
  Vec3 normal;    // unit, outward
  double offset;  // normal . p on the plane [m]
};

// Every vertex against every plane, stopping at the first outside: the definition itself, for
// meshes the fast test does not apply to (open ones) and for vertices no triangle uses.
bool allInside(const Mesh& mesh, const std::vector<FacePlane>& planes, const std::vector<std::uint32_t>& vertices,
               double tolerance) {
  if (double(planes.size()) * double(vertices.size()) > kMaxConvexityWork) return false;
  for (const FacePlane& plane : planes) {
    for (std::uint32_t v : vertices) {
      if (plane.normal.dot(mesh.vertices[v]) - plane.offset > tolerance) return false;
    }
  }
  return true;
}

std::vector<std::uint32_t> everyVertex(const Mesh& mesh) {
  std::vector<std::uint32_t> all(mesh.vertices.size());
  for (std::uint32_t v = 0; v < all.size(); ++v) all[v] = v;
  return all;
}

// The solid angle [sr] triangle abc subtends at the origin (Van Oosterom and Strackee 1983), signed
// by its winding: positive when the origin is behind the triangle.
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

}  // namespace

bool isConvexSurface(const Mesh& mesh, double tolerance) {
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t v : t) {
      if (v >= mesh.vertices.size()) return false;  // no mesh at all (checkMesh says why)
    }
  }
  std::vector<FacePlane> planes;
  planes.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    const double length = n.norm();
    if (length > 0.0) planes.push_back({n / length, n.dot(a) / length});
  }
  const MeshCheck check = checkMesh(mesh);
  std::vector<std::uint32_t> unused;
  std::vector<std::uint32_t> degree(mesh.vertices.size() + 1, 0);
  for (const Triangle& t : mesh.triangles) {
    for (std::uint32_t v : t) ++degree[v];
  }
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    if (degree[v] == 0) unused.push_back(v);
  }
  if (!check.closed || !check.consistentlyOriented || check.degenerateTriangles > 0) {
    return allInside(mesh, planes, everyVertex(mesh), tolerance);
  }
  if (!allInside(mesh, planes, unused, tolerance)) return false;

  // The centroid of the solid (about the box centre, for precision) and the winding around it.
  const Vec3 reference = 0.5 * (mesh.boundsMin() + mesh.boundsMax());
  double sixVolume = 0.0;
  Vec3 weighted = Vec3::Zero();
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - reference, b = mesh.vertices[t[1]] - reference,
               c = mesh.vertices[t[2]] - reference;
    const double six = a.dot(b.cross(c));
    sixVolume += six;
    weighted += six * (a + b + c) / 4.0;
  }
  if (!(sixVolume > 0.0)) return false;
  const Vec3 centroid = reference + weighted / sixVolume;
  double winding = 0.0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!(planes[f].normal.dot(centroid) - planes[f].offset < 0.0)) return false;
    const Triangle& t = mesh.triangles[f];
    winding += solidAngle(mesh.vertices[t[0]] - centroid, mesh.vertices[t[1]] - centroid,
                          mesh.vertices[t[2]] - centroid);
  }
  constexpr double kFullSphere = 4.0 * 3.14159265358979323846;  // [sr]
  if (std::abs(winding - kFullSphere) > 0.5 * kFullSphere) return false;  // wound 0 or 2+ times

  // Vertex graph: on a closed, consistently wound mesh each neighbour w of v follows v in exactly
  // one triangle, so one entry per corner lists every edge once per end.
  std::vector<std::uint32_t> first(mesh.vertices.size() + 1, 0);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) first[v + 1] = first[v] + degree[v];
  std::vector<std::uint32_t> neighbours(first.back());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) neighbours[fill[t[k]]++] = t[(k + 1) % 3];
  }
  double budget = kConvexityWorkPerTriangle * double(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const FacePlane& plane = planes[f];
    const auto height = [&](std::uint32_t v) { return plane.normal.dot(mesh.vertices[v]) - plane.offset; };
    // Steepest ascent from each corner (their neighbours include the far corners of the three
    // adjacent triangles); each step must rise, so it cannot cycle.
    for (std::uint32_t at : mesh.triangles[f]) {
      double atHeight = height(at);
      for (bool rose = true; rose;) {
        if (atHeight > tolerance) return false;
        rose = false;
        const std::uint32_t from = at;
        for (std::uint32_t k = first[from]; k < first[from + 1]; ++k) {
          const double h = height(neighbours[k]);
          if (h > atHeight) {
            at = neighbours[k];
            atHeight = h;
            rose = true;
          }
        }
        budget -= first[from + 1] - first[from];
        // Out of walking budget (fans of many coplanar triangles, as clipping leaves): no witness
        // either way, so the plain test decides, itself bounded by kMaxConvexityWork.
        if (budget < 0.0) return allInside(mesh, planes, everyVertex(mesh), tolerance);
      }
    }
  }
  return true;
}

}  // namespace rbsim
