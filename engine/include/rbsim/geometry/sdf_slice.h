#pragma once
// A plane of one body's signed distance grid, read back for display and for checking how the grid
// was built (seed 000 "Constructing Signed Distance Functions": narrow band, fast marching, sign by
// flood fill): phi at every grid point of one lattice layer, with the stage that set it and the
// flood fill's region, and phi's zero contour across the layer. Read-only: the grid is unchanged.
#include <cstddef>
#include <vector>

#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct SdfSlice {
  int axis = 2;             // the layer's normal: 0 x, 1 y, 2 z (grid frame = body frame)
  int layer = 0;            // its grid index along `axis`
  double offset = 0.0;      // its coordinate along `axis` [m]
  int uAxis = 0, vAxis = 1;  // the in-plane axes: (axis + 1) % 3 and (axis + 2) % 3
  int width = 0, height = 0;  // samples along u and v
  Vec3 corner = Vec3::Zero();  // the sample (0, 0) [m]
  double cellSize = 0.0;       // h, the spacing of the samples [m]
  std::vector<double> phi;             // [m], u fastest: index(u, v)
  std::vector<SdfStage> stage;         // which stage of the build set each sample
  std::vector<SdfFillRegion> region;   // the flood fill's region of each sample

  std::size_t index(int u, int v) const { return static_cast<std::size_t>(v) * width + u; }
  // The sample's point, or any point at fractional sample coordinates (u, v) [m].
  Vec3 point(double u, double v) const;
};

// The lattice layer of `grid` normal to `axis` nearest `offset` [m] (along the axis, in the grid's
// frame). Throws std::invalid_argument when the axis is not 0, 1 or 2, or offset is not finite or
// lies more than half a cell outside the grid's extent along the axis (sdfSliceExtent).
SdfSlice sdfSlice(const SignedDistanceGrid& grid, int axis, double offset);
// The coordinates [m] of the grid's first and last layers along `axis`.
void sdfSliceExtent(const SignedDistanceGrid& grid, int axis, double& first, double& last);

// phi = 0 across the slice by marching squares: in each cell whose corners' signs differ (inside
// is phi < 0), a segment between the points where phi, linear along the cell's edges, is zero; a
// cell with two opposite corners inside and two outside is split by the sign of its centre's
// mean. Segments in sample coordinates (u, v); slice.point() turns them into metres.
struct ContourSegment {
  Eigen::Vector2d a, b;  // (u, v) [samples]
};
std::vector<ContourSegment> sdfZeroContour(const SdfSlice& slice);

}  // namespace rbsim
