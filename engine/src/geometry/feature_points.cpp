#include "geometry/feature_points.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Eigenvalues>

namespace rbsim {

namespace {

// A crossing of the surface with a grid edge: where, and the outward unit normal there (zero
// where the gradient vanishes).
struct Hermite {
  Vec3 point;
  Vec3 normal;
};

// The root of phi on the segment a -> b, whose ends have opposite signs (fa < 0 <= fb or the
// reverse): regula falsi with the Illinois modification (Dowell and Jarratt 1971), which keeps
// bisection's bracket and converges superlinearly.
Vec3 crossing(const Vec3& a, const Vec3& b, double fa, double fb, const ExactField& field) {
  double lo = 0.0, hi = 1.0;
  int side = 0;
  for (int iteration = 0; iteration < 100 && hi - lo > kCrossingTolerance; ++iteration) {
    const double t = (fa == fb) ? 0.5 * (lo + hi) : lo + (hi - lo) * fa / (fa - fb);
    const double f = field.phi(a + t * (b - a));
    if (f == 0.0) return a + t * (b - a);
    if ((f < 0.0) == (fa < 0.0)) {
      lo = t;
      fa = f;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      hi = t;
      fb = f;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return a + 0.5 * (lo + hi) * (b - a);
}

// The minimiser of sum_i (n_i . (x - p_i))^2 nearest the mean c of the p_i: c plus the truncated
// pseudo-inverse of A = sum n n^T applied to sum n (n . (p_i - c)).
Vec3 minimiseQuadraticError(const std::vector<Hermite>& samples) {
  Vec3 mean = Vec3::Zero();
  for (const Hermite& h : samples) mean += h.point;
  mean /= static_cast<double>(samples.size());
  Mat3 a = Mat3::Zero();
  Vec3 rhs = Vec3::Zero();
  for (const Hermite& h : samples) {
    a += h.normal * h.normal.transpose();
    rhs += h.normal * h.normal.dot(h.point - mean);
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(a);
  const double largest = eigen.eigenvalues().maxCoeff();
  Vec3 x = mean;
  if (!(largest > 0.0)) return x;
  for (int k = 0; k < 3; ++k) {
    const double lambda = eigen.eigenvalues()[k];
    if (lambda > kFeatureEigenRatio * largest) {
      const Vec3 v = eigen.eigenvectors().col(k);
      x += v * (v.dot(rhs) / lambda);
    }
  }
  return x;
}

}  // namespace

Vec3 projectOntoSurface(const Vec3& p, const ExactField& field, double tolerance) {
  Vec3 x = p;
  for (int step = 0; step < kProjectionSteps; ++step) {
    const double f = field.phi(x);
    if (!(std::abs(f) > tolerance)) break;
    const Vec3 g = field.gradient(x);
    const double g2 = g.squaredNorm();
    if (!(g2 > 0.0)) break;
    x -= (f / g2) * g;
  }
  return x;
}

std::vector<Vec3> featurePoints(const SignedDistanceGrid& grid, const ExactField& field) {
  const Vec3i dims = grid.dims();
  const double h = grid.cellSize();
  const auto index = [&](int i, int j, int k) {
    return static_cast<std::uint64_t>(i) + static_cast<std::uint64_t>(dims.x()) *
                                               (static_cast<std::uint64_t>(j) + static_cast<std::uint64_t>(dims.y()) * k);
  };
  // Each grid edge's crossing is found once, though up to four cells share it.
  std::unordered_map<std::uint64_t, Hermite> crossings;
  const auto edgeCrossing = [&](const Vec3i& lower, int axis) -> const Hermite& {
    const std::uint64_t key = 3 * index(lower.x(), lower.y(), lower.z()) + static_cast<std::uint64_t>(axis);
    auto it = crossings.find(key);
    if (it != crossings.end()) return it->second;
    Vec3i upper = lower;
    ++upper[axis];
    const Vec3 a = grid.point(lower.x(), lower.y(), lower.z());
    const Vec3 b = grid.point(upper.x(), upper.y(), upper.z());
    const Vec3 p = crossing(a, b, grid.value(lower.x(), lower.y(), lower.z()), grid.value(upper.x(), upper.y(), upper.z()), field);
    const Vec3 g = field.gradient(p);
    const double length = g.norm();
    return crossings.emplace(key, Hermite{p, length > 0.0 ? Vec3(g / length) : Vec3::Zero()}).first->second;
  };
  std::vector<Vec3> points;
  std::vector<Hermite> samples;
  for (int k = 0; k + 1 < dims.z(); ++k) {
    for (int j = 0; j + 1 < dims.y(); ++j) {
      for (int i = 0; i + 1 < dims.x(); ++i) {
        samples.clear();
        // The cell's 12 edges: from each corner with a 0 coordinate along `axis`, one step along it.
        for (int axis = 0; axis < 3; ++axis) {
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          for (int corner = 0; corner < 4; ++corner) {
            Vec3i lower(i, j, k);
            lower[u] += corner & 1;
            lower[v] += corner >> 1;
            Vec3i upper = lower;
            ++upper[axis];
            const bool inLower = grid.value(lower.x(), lower.y(), lower.z()) < 0.0;
            const bool inUpper = grid.value(upper.x(), upper.y(), upper.z()) < 0.0;
            if (inLower != inUpper) samples.push_back(edgeCrossing(lower, axis));
          }
        }
        if (samples.empty()) continue;
        Vec3 x = minimiseQuadraticError(samples);
        // A minimiser outside the cell belongs to a feature of another cell: this cell keeps the
        // crossings' mean, which is on its own piece of the surface.
        const Vec3 lo = grid.point(i, j, k), hi = lo + Vec3::Constant(h);
        const double slack = 1e-9 * h;
        if ((x.array() < lo.array() - slack).any() || (x.array() > hi.array() + slack).any()) {
          x = Vec3::Zero();
          for (const Hermite& s : samples) x += s.point;
          x /= static_cast<double>(samples.size());
        }
        points.push_back(projectOntoSurface(x, field, kCrossingTolerance * h));
      }
    }
  }
  return points;
}

}  // namespace rbsim
