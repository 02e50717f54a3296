// A convex solid as the intersection of its face planes (shapes/face_planes.h).
#include "rbsim/shapes/face_planes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace rbsim {

namespace {
// Faces whose normals and offsets agree this closely are one plane (a box face's two triangles).
constexpr double kSamePlaneTolerance = 1e-9;  // [1] and [m]

// The planes found so far, bucketed on a grid of kSamePlaneTolerance in (normal, offset): a plane
// within the tolerance of a new one lies in the new one's cell or a neighbouring one, so each
// triangle looks at 3^4 cells instead of every plane (a 1e5-face convex mesh took minutes).
class PlaneBuckets {
 public:
  // The index of a known plane within tolerance of (unit, offset), or -1.
  long find(const FacePlanes& shape, const Vec3& unit, double offset) const {
    const Key centre = keyOf(unit, offset);
    for (int code = 0; code < 81; ++code) {
      Key key = centre;
      for (int axis = 0, rest = code; axis < 4; ++axis, rest /= 3) key[axis] += rest % 3 - 1;
      const auto bucket = buckets_.find(key);
      if (bucket == buckets_.end()) continue;
      for (const std::size_t f : bucket->second) {
        if ((shape.normals[f] - unit).norm() < kSamePlaneTolerance && std::abs(shape.offsets[f] - offset) < kSamePlaneTolerance) {
          return static_cast<long>(f);
        }
      }
    }
    return -1;
  }
  void add(const Vec3& unit, double offset, std::size_t index) { buckets_[keyOf(unit, offset)].push_back(index); }

 private:
  using Key = std::array<std::int64_t, 4>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = 0;
      for (const std::int64_t v : k) h = h * 1000003u ^ std::hash<std::int64_t>()(v);
      return h;
    }
  };
  // Saturated far from the origin: a shared cell there only costs a longer scan, never a wrong answer.
  static std::int64_t cell(double x) {
    const double c = std::floor(x / kSamePlaneTolerance);
    constexpr double kLimit = 1e18;
    return static_cast<std::int64_t>(std::max(-kLimit, std::min(kLimit, c)));
  }
  static Key keyOf(const Vec3& unit, double offset) { return {cell(unit.x()), cell(unit.y()), cell(unit.z()), cell(offset)}; }
  std::unordered_map<Key, std::vector<std::size_t>, KeyHash> buckets_;
};

}  // namespace

FacePlanes facePlanesOf(const Mesh& mesh) {
  FacePlanes shape;
  for (const Vec3& p : mesh.vertices) shape.boundingRadius = std::max(shape.boundingRadius, p.norm());
  PlaneBuckets known;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    if (!(n.norm() > 0.0)) continue;  // degenerate: no plane
    const Vec3 unit = n.normalized();
    const double offset = unit.dot(a);
    if (known.find(shape, unit, offset) >= 0) continue;
    known.add(unit, offset, shape.normals.size());
    shape.normals.push_back(unit);
    shape.offsets.push_back(offset);
  }
  return shape;
}

FaceDistance nearestFace(const FacePlanes& shape, const Vec3& local) {
  FaceDistance out{0, -std::numeric_limits<double>::infinity()};
  for (std::size_t f = 0; f < shape.normals.size(); ++f) {
    const double d = shape.normals[f].dot(local) - shape.offsets[f];
    if (d > out.distance) out = {f, d};
  }
  return out;
}

}  // namespace rbsim
