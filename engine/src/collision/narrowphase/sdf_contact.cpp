#include "collision/narrowphase/sdf_contact.h"

#include <algorithm>
#include <cmath>

#include "collision/narrowphase/manifold_reduction.h"

namespace rbsim {

namespace {

// The surface points of `body` that lie within `margin` of `solid`'s surface, as contacts whose
// normal points from A to B: the solid's outward normal when the solid is A, its inverse when the
// solid is B.
void pointsAgainstSolid(const RigidBody& body, const BodySolid& bodySolid, const RigidBody& solid,
                        const BodySolid& solidShape, double margin, bool solidIsA, std::vector<PointContact>& out) {
  const Mat3& R = body.rotation();
  const Mat3& Rs = solid.rotation();
  const Mat3 RsT = Rs.transpose();
  const double reach = solidShape.convex.boundingRadius + margin;
  const std::vector<Vec3>& samples = bodySolid.samples ? *bodySolid.samples : body.mesh().vertices;
  for (const Vec3& p : samples) {
    const Vec3 world = R * p + body.position();
    const Vec3 arm = world - solid.position();
    if (arm.squaredNorm() > reach * reach) continue;
    const SurfaceQuery q = querySurface(solidShape, RsT * arm);  // x_o = R^T (x_w - x)
    if (!(q.distance <= margin)) continue;
    const Vec3 outward = Rs * q.normal;
    const double depth = -q.distance;
    out.push_back({world + 0.5 * depth * outward, solidIsA ? outward : Vec3(-outward), depth});
  }
}

}  // namespace

std::vector<ContactManifold> collideSdf(const RigidBody& a, const BodySolid& shapeA, const RigidBody& b,
                                        const BodySolid& shapeB, double margin) {
  std::vector<PointContact> points;
  pointsAgainstSolid(a, shapeA, b, shapeB, margin, /*solidIsA=*/false, points);
  pointsAgainstSolid(b, shapeB, a, shapeA, margin, /*solidIsA=*/true, points);
  return manifoldsByNormal(points);
}

std::vector<ContactManifold> manifoldsByNormal(std::vector<PointContact>& points) {
  std::vector<ContactManifold> manifolds;
  if (points.empty()) return manifolds;
  // Deepest first, so each group's normal is that of its deepest point; ties broken by position
  // so the grouping does not depend on the sort's stability.
  std::sort(points.begin(), points.end(), [](const PointContact& x, const PointContact& y) {
    if (x.depth != y.depth) return x.depth > y.depth;
    return std::lexicographical_compare(x.position.data(), x.position.data() + 3, y.position.data(), y.position.data() + 3);
  });
  const double sameDirection = std::cos(kSdfManifoldAngle);
  std::vector<Vec3> normals;
  std::vector<std::vector<ContactPoint>> groups;
  for (const PointContact& p : points) {
    std::size_t best = groups.size();
    double bestAlignment = -2.0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const double alignment = normals[g].dot(p.normal);
      if (alignment > bestAlignment) {
        bestAlignment = alignment;
        best = g;
      }
    }
    if (best == groups.size() || (bestAlignment < sameDirection && groups.size() < static_cast<std::size_t>(kMaxSdfManifolds))) {
      normals.push_back(p.normal);
      groups.emplace_back();
      best = groups.size() - 1;
    }
    // Along the group's normal the point is this deep (its own normal may differ a little).
    groups[best].push_back({p.position, p.depth * normals[best].dot(p.normal)});
  }
  for (std::size_t g = 0; g < groups.size(); ++g) manifolds.push_back(reduceContacts(groups[g], normals[g]));
  return manifolds;
}

}  // namespace rbsim
