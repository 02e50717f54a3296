#include "rbsim/soft/tet_mesh.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace rbsim {

namespace {

double signedVolume(const std::vector<Vec3>& x, const Tet& t) {
  return (x[t[1]] - x[t[0]]).dot((x[t[2]] - x[t[0]]).cross(x[t[3]] - x[t[0]])) / 6.0;
}

}  // namespace

TetMesh makeTetBox(const Vec3& extents, int nx, int ny, int nz) {
  if (!(extents.minCoeff() > 0.0) || !extents.allFinite() || nx < 1 || ny < 1 || nz < 1) {
    throw std::invalid_argument("makeTetBox: expected positive extents and at least one cell per axis");
  }
  TetMesh mesh;
  const auto index = [&](int i, int j, int k) { return static_cast<std::uint32_t>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        mesh.nodes.push_back(Vec3(extents.x() * (static_cast<double>(i) / nx - 0.5),
                                  extents.y() * (static_cast<double>(j) / ny - 0.5),
                                  extents.z() * (static_cast<double>(k) / nz - 0.5)));
      }
    }
  }
  // Kuhn's six tetrahedra of the unit cube: paths from corner 000 to 111 along the axes in every
  // order (x, y, z permutations).
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        for (const auto& order : orders) {
          int c[3] = {i, j, k};
          Tet t;
          t[0] = index(c[0], c[1], c[2]);
          for (int step = 0; step < 3; ++step) {
            ++c[order[step]];
            t[step + 1] = index(c[0], c[1], c[2]);
          }
          if (signedVolume(mesh.nodes, t) < 0.0) std::swap(t[2], t[3]);
          mesh.tets.push_back(t);
        }
      }
    }
  }
  mesh.boundary = boundaryFaces(mesh.nodes, mesh.tets);
  return mesh;
}

std::vector<std::array<std::uint32_t, 3>> boundaryFaces(const std::vector<Vec3>& nodes, const std::vector<Tet>& tets) {
  // Each face of a positively oriented tetrahedron, wound so that its normal points away from
  // the fourth node; faces seen twice are interior.
  std::map<std::array<std::uint32_t, 3>, std::pair<int, std::array<std::uint32_t, 3>>> faces;
  const int corners[4][4] = {{1, 2, 3, 0}, {0, 3, 2, 1}, {0, 1, 3, 2}, {0, 2, 1, 3}};
  for (const Tet& t : tets) {
    for (const auto& c : corners) {
      std::array<std::uint32_t, 3> face = {t[c[0]], t[c[1]], t[c[2]]};
      const Vec3 normal = (nodes[face[1]] - nodes[face[0]]).cross(nodes[face[2]] - nodes[face[0]]);
      if (normal.dot(nodes[t[c[3]]] - nodes[face[0]]) > 0.0) std::swap(face[1], face[2]);
      std::array<std::uint32_t, 3> key = face;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      ++entry.first;
      entry.second = face;
    }
  }
  std::vector<std::array<std::uint32_t, 3>> boundary;
  for (const auto& [key, entry] : faces) {
    if (entry.first == 1) boundary.push_back(entry.second);
  }
  return boundary;
}

std::string checkTetMesh(const TetMesh& mesh) {
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    for (std::uint32_t n : mesh.tets[i]) {
      if (n >= mesh.nodes.size()) return "tetrahedron " + std::to_string(i) + " names a node that does not exist";
    }
    if (!(signedVolume(mesh.nodes, mesh.tets[i]) > 0.0)) {
      return "tetrahedron " + std::to_string(i) + " has zero or negative volume (expected positive orientation)";
    }
  }
  return {};
}

}  // namespace rbsim
