#include "collision/narrowphase/convex_plane.h"

#include <algorithm>
#include <limits>

#include "collision/narrowphase/manifold_reduction.h"

namespace rbsim {

ContactManifold collidePlaneConvex(const Plane& plane, const std::vector<Vec3>& vertices, double margin,
                                   double supportSlab) {
  // Scratch kept per thread (the narrow phase collides on several): a step collides every body
  // near a plane, and allocating here was most of a settled pyramid's allocations per step.
  thread_local std::vector<ContactPoint> candidates, visible;
  candidates.clear();
  visible.clear();
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : vertices) {
    const double s = plane.signedDistance(p);
    if (s > margin) continue;
    candidates.push_back({p - plane.normal * (0.5 * s), -s});
    deepest = std::max(deepest, -s);
  }
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const ContactPoint& c) { return c.depth < deepest - supportSlab; }),
                   candidates.end());
  // A vertex above a deeper one, higher by more than it lies beside it, is shadowed: the deeper
  // vertex meets the plane first and holds the body there. Reduction by area sees the plane's
  // projection only, so without this it may keep the top corner of a thin plate (within the
  // margin, at the same place seen from above) and drop the bottom corner under it, which then
  // sinks unopposed.
  for (const ContactPoint& c : candidates) {
    const bool shadowed = std::any_of(candidates.begin(), candidates.end(), [&](const ContactPoint& d) {
      const Vec3 beside = d.position - c.position - plane.normal * plane.normal.dot(d.position - c.position);
      return d.depth - c.depth > beside.norm();
    });
    if (!shadowed) visible.push_back(c);
  }
  return reduceContacts(visible, plane.normal);
}

}  // namespace rbsim
