#pragma once
// The lattice of a signed distance grid: points origin + h (i, j, k), stored x fastest.
#include <cstddef>

#include "rbsim/math/types.h"

namespace rbsim {

using Vec3i = Eigen::Vector3i;

struct GridLattice {
  Vec3 origin = Vec3::Zero();  // position of point (0, 0, 0) [m]
  double cellSize = 1.0;       // h [m]
  Vec3i dims = Vec3i::Ones();  // points per axis

  std::size_t pointCount() const {
    return static_cast<std::size_t>(dims.x()) * dims.y() * dims.z();
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(dims.x()) *
                                             (static_cast<std::size_t>(j) +
                                              static_cast<std::size_t>(dims.y()) * k);
  }
  Vec3i coordinates(std::size_t index) const {
    const int i = static_cast<int>(index % dims.x());
    const std::size_t rest = index / dims.x();
    return {i, static_cast<int>(rest % dims.y()), static_cast<int>(rest / dims.y())};
  }
  Vec3 point(int i, int j, int k) const { return origin + cellSize * Vec3(i, j, k); }
  // Index offset of one step along an axis.
  std::size_t stride(int axis) const {
    return axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(dims.x())
                                     : static_cast<std::size_t>(dims.x()) * dims.y();
  }
};

}  // namespace rbsim
