#include "collision/narrowphase/convex_plane.h"

#include "collision/narrowphase/manifold_reduction.h"

namespace rbsim {

ContactManifold collidePlaneConvex(const Plane& plane, const std::vector<Vec3>& vertices, double margin) {
  std::vector<ContactPoint> candidates;
  for (const Vec3& p : vertices) {
    const double s = plane.signedDistance(p);
    if (s <= margin) candidates.push_back({p - plane.normal * (0.5 * s), -s});
  }
  return reduceContacts(candidates, plane.normal);
}

}  // namespace rbsim
