#pragma once
// Shared by the narrow-phase suites: box corners and signed distance, rotations, random rotations,
// and an unbiased 15-axis SAT reference.
#include <cmath>
#include <random>
#include <vector>

#include "collision/narrowphase/box_box.h"
#include "rbsim/math/types.h"

namespace rbsim::test {

inline Mat3 rotationAbout(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

inline Mat3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  return Quat(Eigen::Vector4d(g(rng), g(rng), g(rng), g(rng)).normalized()).toRotationMatrix();
}

inline OrientedBox makeOrientedBox(const Vec3& centre, const Vec3& halfExtents, const Mat3& R = Mat3::Identity()) {
  OrientedBox b;
  b.centre = centre;
  b.rotation = R;
  b.halfExtents = halfExtents;
  return b;
}

// The 8 corners in makeBox's order (the seed's p0..p7), in world frame.
inline std::vector<Vec3> boxCorners(const OrientedBox& b) {
  std::vector<Vec3> out;
  for (int k = 0; k < 8; ++k) {
    const Vec3 s((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : -1, (k == 2 || k == 3 || k == 6 || k == 7) ? 1 : -1,
                 k >= 4 ? 1 : -1);
    out.push_back(b.centre + b.rotation * s.cwiseProduct(b.halfExtents));
  }
  return out;
}

// Signed distance from p to the box's surface [m]: < 0 inside.
inline double boxSignedDistance(const OrientedBox& b, const Vec3& p) {
  const Vec3 q = (b.rotation.transpose() * (p - b.centre)).cwiseAbs() - b.halfExtents;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

// Largest separation over all 15 SAT axes, without any preference: > 0 apart, and for
// overlapping boxes -(penetration depth) exactly (the minimum translation distance of polytopes
// is along a face normal or an edge-edge cross product).
inline double satSeparation(const OrientedBox& a, const OrientedBox& b, Vec3* axis = nullptr) {
  std::vector<Vec3> axes;
  for (int i = 0; i < 3; ++i) {
    axes.push_back(a.rotation.col(i));
    axes.push_back(b.rotation.col(i));
    for (int j = 0; j < 3; ++j) {
      const Vec3 c = a.rotation.col(i).cross(b.rotation.col(j));
      if (c.norm() > 1e-9) axes.push_back(c.normalized());
    }
  }
  const Vec3 d = b.centre - a.centre;
  double best = -1e300;
  for (const Vec3& L : axes) {
    double r = 0.0;
    for (int k = 0; k < 3; ++k) {
      r += a.halfExtents[k] * std::abs(L.dot(a.rotation.col(k))) + b.halfExtents[k] * std::abs(L.dot(b.rotation.col(k)));
    }
    const double s = std::abs(L.dot(d)) - r;
    if (s > best) {
      best = s;
      if (axis != nullptr) *axis = L.dot(d) >= 0.0 ? L : Vec3(-L);
    }
  }
  return best;
}

}  // namespace rbsim::test
