#include "geometry/marching_tetrahedra.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace rbsim {

namespace {

// Kuhn's six tetrahedra of the unit cell: for each order (i, j, k) of the axes, the path
// 000 -> e_i -> e_i + e_j -> 111. Each corner is a bit mask x = 1, y = 2, z = 4.
constexpr std::array<std::array<int, 4>, 6> kTetrahedra{{
    {0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

class Mesher {
 public:
  Mesher(const GridLattice& grid, const std::vector<double>& values, MarchingStats& stats)
      : grid_(grid), values_(values), stats_(stats), zeroBand_(kMarchingZeroBand * grid.cellSize) {}

  void cell(int i, int j, int k) {
    std::array<std::size_t, 8> index{};
    std::array<Vec3, 8> point;
    std::array<double, 8> value{};
    for (int c = 0; c < 8; ++c) {
      const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
      index[c] = grid_.index(i + di, j + dj, k + dk);
      point[c] = grid_.point(i + di, j + dj, k + dk);
      const double v = values_[index[c]];
      value[c] = std::abs(v) <= zeroBand_ ? 0.0 : v;
    }
    for (const auto& tet : kTetrahedra) tetrahedron(tet, index, point, value);
  }

  Mesh take() { return std::move(mesh_); }

 private:
  struct Corner {
    std::size_t index;
    Vec3 point;
    double value;
  };

  void tetrahedron(const std::array<int, 4>& tet, const std::array<std::size_t, 8>& index,
                   const std::array<Vec3, 8>& point, const std::array<double, 8>& value) {
    std::array<Corner, 4> in{}, out{};
    int nIn = 0, nOut = 0;
    for (const int c : tet) {
      const Corner corner{index[c], point[c], value[c]};
      if (value[c] < 0.0) in[nIn++] = corner; else out[nOut++] = corner;
    }
    if (nIn == 0 || nOut == 0) return;
    Vec3 inCentre = Vec3::Zero(), outCentre = Vec3::Zero();
    for (int a = 0; a < nIn; ++a) inCentre += in[a].point / nIn;
    for (int a = 0; a < nOut; ++a) outCentre += out[a].point / nOut;
    const Vec3 outward = outCentre - inCentre;  // along the linear interpolant's gradient
    if (nIn == 1 || nOut == 1) {
      const Corner& apex = nIn == 1 ? in[0] : out[0];
      const std::array<Corner, 4>& others = nIn == 1 ? out : in;
      triangle({edge(apex, others[0]), edge(apex, others[1]), edge(apex, others[2])}, outward);
      return;
    }
    // Two and two: the quadrilateral in0-out0, in0-out1, in1-out1, in1-out0 (around its boundary).
    const Edge a = edge(in[0], out[0]), b = edge(in[0], out[1]), c = edge(in[1], out[1]), d = edge(in[1], out[0]);
    triangle({a, b, c}, outward);
    triangle({a, c, d}, outward);
  }

  struct Edge {
    std::uint64_t key;
    Vec3 exact;  // the zero of the linear interpolation, before snapping
    Vec3 placed;
  };

  Edge edge(const Corner& p, const Corner& q) {
    const double t = p.value / (p.value - q.value);
    const Vec3 exact = p.point + t * (q.point - p.point);
    // A grid point's key is 2 * index; an edge's 2 * (first index) * 8 + 1 + the offset's bit mask.
    // Only an end of value zero (outside, t = 1) holds a vertex; any other crossing is inside the
    // edge, apart from both ends (for a distance, by at least 1e-6 cells / sqrt(3)).
    if (q.value == 0.0 || p.value == 0.0) {
      const Corner& at = q.value == 0.0 ? q : p;
      return {2 * static_cast<std::uint64_t>(at.index), exact, at.point};
    }
    const bool pFirst = p.index < q.index;
    const Corner& lo = pFirst ? p : q;
    const Corner& hi = pFirst ? q : p;
    const Vec3 step = (hi.point - lo.point) / grid_.cellSize;
    const int mask = (step.x() > 0.5 ? 1 : 0) | (step.y() > 0.5 ? 2 : 0) | (step.z() > 0.5 ? 4 : 0);
    // From the lower index's end, so that every tetrahedron around the edge places it alike.
    const double s = std::clamp(lo.value / (lo.value - hi.value), kMarchingVertexMargin, 1.0 - kMarchingVertexMargin);
    const Vec3 placed = lo.point + s * (hi.point - lo.point);
    return {2 * (static_cast<std::uint64_t>(lo.index) * 8 + static_cast<std::uint64_t>(mask)) + 1, exact, placed};
  }

  std::uint32_t vertex(const Edge& e) {
    const auto [it, added] = vertexOf_.emplace(e.key, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (added) {
      mesh_.vertices.push_back(e.placed);
      if ((e.key & 1) == 0) ++stats_.snappedVertices;
    }
    return it->second;
  }

  // Winds the triangle so that its normal, from the unsnapped positions, points along `outward`.
  void triangle(std::array<Edge, 3> e, const Vec3& outward) {
    if ((e[1].exact - e[0].exact).cross(e[2].exact - e[0].exact).dot(outward) < 0.0) std::swap(e[1], e[2]);
    const Triangle t{vertex(e[0]), vertex(e[1]), vertex(e[2])};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++stats_.droppedTriangles;
      return;
    }
    mesh_.triangles.push_back(t);
  }

  const GridLattice& grid_;
  const std::vector<double>& values_;
  MarchingStats& stats_;
  const double zeroBand_;  // [m]
  Mesh mesh_;
  std::unordered_map<std::uint64_t, std::uint32_t> vertexOf_;
};

}  // namespace

Mesh marchingTetrahedra(const GridLattice& grid, const std::vector<double>& values, MarchingStats* stats) {
  if (values.size() != grid.pointCount()) {
    throw std::invalid_argument("marchingTetrahedra: " + std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(grid.pointCount()) + " points");
  }
  MarchingStats local;
  MarchingStats& s = stats ? *stats : local;
  s = MarchingStats{};
  for (const double v : values) {
    if (!std::isfinite(v)) throw std::invalid_argument("marchingTetrahedra: a value is not finite");
    if (v < -kMarchingZeroBand * grid.cellSize) ++s.insidePoints;
  }
  Mesher mesher(grid, values, s);
  if (s.insidePoints > 0) {
    for (int k = 0; k + 1 < grid.dims.z(); ++k) {
      for (int j = 0; j + 1 < grid.dims.y(); ++j) {
        for (int i = 0; i + 1 < grid.dims.x(); ++i) mesher.cell(i, j, k);
      }
    }
  }
  Mesh mesh = mesher.take();
  mesh.name = "implicit surface";
  return mesh;
}

}  // namespace rbsim
