#include "rbsim/world/ray_cast.h"

#include "rbsim/world/world_queries.h"

namespace rbsim {

std::optional<WorldRayHit> rayCast(const World& world, const Vec3& origin, const Vec3& direction, double maxDistance) {
  const std::optional<QueryHit> hit = castRay(world, origin, direction, maxDistance);
  if (!hit) return std::nullopt;
  WorldRayHit out;
  out.isPlane = hit->isPlane;
  out.body = hit->body;
  out.shape = hit->shape;
  out.plane = hit->plane;
  out.distance = hit->distance;
  out.point = hit->point;
  out.normal = hit->normal;
  return out;
}

}  // namespace rbsim
