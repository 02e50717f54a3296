#include "geometry/fast_marching.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace rbsim {

namespace {

// The smallest d with sum over the given upwind values a_i of (d - a_i)^2 = h^2 and d >= every a_i
// used: add the axes in increasing order while the solution exceeds the next value.
double upwindSolve(double a[3], int count, double h) {
  std::sort(a, a + count);
  double d = a[0] + h;
  if (count == 1 || d <= a[1]) return d;
  // Two axes: 2 d^2 - 2 (a0 + a1) d + a0^2 + a1^2 - h^2 = 0; |a0 - a1| < h here, so the
  // discriminant is positive.
  const double diff = a[0] - a[1];
  d = 0.5 * (a[0] + a[1] + std::sqrt(2.0 * h * h - diff * diff));
  if (count == 2 || d <= a[2]) return d;
  const double s = a[0] + a[1] + a[2];
  const double s2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  return (s + std::sqrt(std::max(s * s - 3.0 * (s2 - h * h), 0.0))) / 3.0;
}

}  // namespace

std::size_t fastMarch(const GridLattice& shape, std::vector<MarchLabel>& labels,
                      std::vector<double>& distance) {
  using Entry = std::pair<double, std::size_t>;  // (tentative distance, point): min-heap order
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  const double h = shape.cellSize;

  // The estimate of point p from its Black neighbours (at least one exists when called).
  const auto estimate = [&](std::size_t p) {
    const Vec3i c = shape.coordinates(p);
    double a[3];
    int count = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const std::size_t step = shape.stride(axis);
      double best = std::numeric_limits<double>::infinity();
      if (c[axis] > 0 && labels[p - step] == MarchLabel::Black) best = distance[p - step];
      if (c[axis] + 1 < shape.dims[axis] && labels[p + step] == MarchLabel::Black) {
        best = std::min(best, distance[p + step]);
      }
      if (best < std::numeric_limits<double>::infinity()) a[count++] = best;
    }
    return upwindSolve(a, count, h);
  };
  // Re-estimates the non-Black neighbours of a point that has just turned Black.
  const auto relaxNeighbours = [&](std::size_t p) {
    const Vec3i c = shape.coordinates(p);
    for (int axis = 0; axis < 3; ++axis) {
      const std::size_t step = shape.stride(axis);
      for (int side = 0; side < 2; ++side) {
        if (side == 0 ? c[axis] == 0 : c[axis] + 1 == shape.dims[axis]) continue;
        const std::size_t q = side == 0 ? p - step : p + step;
        if (labels[q] == MarchLabel::Black) continue;
        const double d = estimate(q);
        if (labels[q] == MarchLabel::White || d < distance[q]) {
          labels[q] = MarchLabel::Red;
          distance[q] = d;
          heap.emplace(d, q);
        }
      }
    }
  };

  for (std::size_t p = 0; p < labels.size(); ++p) {
    if (labels[p] == MarchLabel::Black) relaxNeighbours(p);
  }
  std::size_t marched = 0;
  while (!heap.empty()) {
    const auto [d, p] = heap.top();
    heap.pop();
    // Lazy deletion: a point already Black, or an entry superseded by a smaller estimate.
    if (labels[p] == MarchLabel::Black || d != distance[p]) continue;
    labels[p] = MarchLabel::Black;
    ++marched;
    relaxNeighbours(p);
  }
  return marched;
}

}  // namespace rbsim
