#include "collision/narrowphase/manifold_reduction.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace rbsim {

ContactManifold reduceContacts(const ContactPoint* candidates, std::size_t count, const Vec3& normal) {
  ContactManifold m;
  m.normal = normal;
  if (count == 0) return m;
  const auto at = [&](std::size_t i) { return candidates[i].position; };
  // Twice the signed area of (a, b, c) seen along the normal (positive counter-clockwise).
  const auto area2 = [&](const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a).dot(normal); };
  const auto inPlane = [&](const Vec3& d) { return d - normal * normal.dot(d); };

  std::size_t i0 = 0;
  for (std::size_t i = 1; i < count; ++i) {
    if (candidates[i].depth > candidates[i0].depth) i0 = i;
  }
  m.add(at(i0), candidates[i0].depth);

  std::size_t i1 = i0;
  double far = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double d = inPlane(at(i) - at(i0)).norm();
    if (d > far) {
      far = d;
      i1 = i;
    }
  }
  if (far <= kReductionTolerance) return m;

  std::size_t i2 = i0;
  double big = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double a = std::abs(area2(at(i0), at(i1), at(i)));
    if (a > big) {
      big = a;
      i2 = i;
    }
  }
  if (big <= kReductionTolerance * far) {  // every candidate is within tolerance of line i0-i1
    m.add(at(i1), candidates[i1].depth);
    return m;
  }
  if (area2(at(i0), at(i1), at(i2)) < 0.0) std::swap(i1, i2);  // counter-clockwise about normal
  m.add(at(i1), candidates[i1].depth);
  m.add(at(i2), candidates[i2].depth);

  // The fourth point: the largest area a candidate adds beyond one of the triangle's edges.
  const std::size_t tri[3] = {i0, i1, i2};
  std::size_t i3 = i0;
  double added = 0.0, edgeLength = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    for (int e = 0; e < 3; ++e) {
      const Vec3& a = at(tri[e]);
      const Vec3& b = at(tri[(e + 1) % 3]);
      const double outside = -area2(a, b, at(i));
      if (outside > added) {
        added = outside;
        edgeLength = inPlane(b - a).norm();
        i3 = i;
      }
    }
  }
  if (added > kReductionTolerance * edgeLength) m.add(at(i3), candidates[i3].depth);
  return m;
}

}  // namespace rbsim
