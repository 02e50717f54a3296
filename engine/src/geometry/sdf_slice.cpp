#include "rbsim/geometry/sdf_slice.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rbsim {

namespace {

// An offset may lie this far beyond the first or last layer and still pick it: the nearest
// layer is then less than a cell away, as for any offset inside.
constexpr double kSliceSlackCells = 0.5;  // [cells]

// Where phi is zero between two samples of opposite sign, as a fraction of the way from a to b.
double zeroAt(double a, double b) { return a / (a - b); }

}  // namespace

Vec3 SdfSlice::point(double u, double v) const {
  Vec3 p = corner;
  p[uAxis] += u * cellSize;
  p[vAxis] += v * cellSize;
  return p;
}

void sdfSliceExtent(const SignedDistanceGrid& grid, int axis, double& first, double& last) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("sdfSlice: axis " + std::to_string(axis) + ", expected 0, 1 or 2");
  first = grid.origin()[axis];
  last = first + grid.cellSize() * (grid.dims()[axis] - 1);
}

SdfSlice sdfSlice(const SignedDistanceGrid& grid, int axis, double offset) {
  double first = 0.0, last = 0.0;
  sdfSliceExtent(grid, axis, first, last);
  const double h = grid.cellSize();
  if (!std::isfinite(offset) || offset < first - kSliceSlackCells * h || offset > last + kSliceSlackCells * h) {
    throw std::invalid_argument("sdfSlice: offset " + std::to_string(offset) + " m lies outside the grid's " +
                                std::to_string(first) + " to " + std::to_string(last) + " m along axis " +
                                std::to_string(axis));
  }
  SdfSlice s;
  s.axis = axis;
  s.uAxis = (axis + 1) % 3;
  s.vAxis = (axis + 2) % 3;
  s.layer = static_cast<int>(std::lround((offset - first) / h));
  if (s.layer < 0) s.layer = 0;
  if (s.layer > grid.dims()[axis] - 1) s.layer = grid.dims()[axis] - 1;
  s.offset = first + h * s.layer;
  s.width = grid.dims()[s.uAxis];
  s.height = grid.dims()[s.vAxis];
  s.cellSize = h;
  Vec3i c = Vec3i::Zero();
  c[axis] = s.layer;
  s.corner = grid.point(c.x(), c.y(), c.z());
  const std::size_t n = static_cast<std::size_t>(s.width) * s.height;
  s.phi.resize(n);
  s.stage.resize(n);
  s.region.resize(n);
  for (int v = 0; v < s.height; ++v) {
    for (int u = 0; u < s.width; ++u) {
      c[s.uAxis] = u;
      c[s.vAxis] = v;
      const std::size_t i = s.index(u, v);
      s.phi[i] = grid.value(c.x(), c.y(), c.z());
      s.stage[i] = grid.stage(c.x(), c.y(), c.z());
      s.region[i] = grid.fillRegion(c.x(), c.y(), c.z());
    }
  }
  return s;
}

std::vector<ContourSegment> sdfZeroContour(const SdfSlice& s) {
  std::vector<ContourSegment> out;
  using P = Eigen::Vector2d;
  for (int v = 0; v + 1 < s.height; ++v) {
    for (int u = 0; u + 1 < s.width; ++u) {
      // Corners counter-clockwise from (u, v); edge e runs from corner e to corner e + 1.
      const double phi[4] = {s.phi[s.index(u, v)], s.phi[s.index(u + 1, v)], s.phi[s.index(u + 1, v + 1)],
                             s.phi[s.index(u, v + 1)]};
      const P corner[4] = {P(u, v), P(u + 1, v), P(u + 1, v + 1), P(u, v + 1)};
      P cut[4];
      bool cuts[4];
      int count = 0;
      for (int e = 0; e < 4; ++e) {
        const double a = phi[e], b = phi[(e + 1) % 4];
        cuts[e] = (a < 0.0) != (b < 0.0);
        if (!cuts[e]) continue;
        cut[e] = corner[e] + zeroAt(a, b) * (corner[(e + 1) % 4] - corner[e]);
        ++count;
      }
      if (count == 2) {
        int e0 = -1, e1 = -1;
        for (int e = 0; e < 4; ++e) {
          if (cuts[e]) (e0 < 0 ? e0 : e1) = e;
        }
        out.push_back({cut[e0], cut[e1]});
      } else if (count == 4) {
        // A saddle: the centre's mean decides whether the inside corners 0 and 2 connect.
        const bool centreInside = 0.25 * (phi[0] + phi[1] + phi[2] + phi[3]) < 0.0;
        const bool zeroInside = phi[0] < 0.0;
        if (centreInside == zeroInside) {  // corners 0 and 2 joined: cut off corners 1 and 3
          out.push_back({cut[0], cut[1]});
          out.push_back({cut[2], cut[3]});
        } else {  // cut off corners 0 and 2
          out.push_back({cut[3], cut[0]});
          out.push_back({cut[1], cut[2]});
        }
      }
    }
  }
  return out;
}

}  // namespace rbsim
