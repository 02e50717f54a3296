// The scene queries (world/world_queries.h): argument checks, one walk of the World's tree
// (world/query_tree.h) per query, each body it reaches answered exactly (world/body_queries.h),
// the planes, few, all tested.
#include "rbsim/world/world_queries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "rbsim/collision/shape_queries.h"
#include "rbsim/world/world.h"
#include "world/body_queries.h"
#include "world/query_tree.h"
#include "world/world_access.h"

namespace rbsim {

namespace {

// The unit direction of a cast, after checking the arguments; `call` names it in the message.
Vec3 checkedCastDirection(const std::string& call, const Vec3& direction, double maxDistance) {
  // stableNorm, not norm: sqrt of the squared norm is 0 below 1e-154 and inf above 1e154, and a
  // direction of any finite length is a direction (issue 56).
  const double length = direction.stableNorm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::invalid_argument(call + ": expected a non-zero, finite direction");
  }
  if (!(maxDistance >= 0.0)) throw std::invalid_argument(call + ": expected a max distance >= 0");
  return direction / length;
}

// The hit's body and shape, body i's child hit (its one shape for a body of one shape).
void nameBody(const World& world, std::uint32_t i, QueryHit& hit) {
  hit.body = world.idAt(i);
  hit.shape = WorldAccess::shapeIdOf(world, i, hit.child < 0 ? 0 : static_cast<std::size_t>(hit.child));
}

void checkFinitePoint(const std::string& call, const char* field, const Vec3& p) {
  if (!p.allFinite()) throw std::invalid_argument(call + ": expected a finite " + field);
}

std::optional<QueryHit> castOneRay(const World& world, const QueryTree& tree, const Vec3& origin, const Vec3& d,
                                double maxDistance, const QueryFilter& filter) {
  std::optional<QueryHit> best;
  double reach = maxDistance;  // shrinks to the nearest hit so far
  tree.walkRay(origin, d, reach, Vec3::Zero(), [&](std::uint32_t i, std::uint32_t slot, double& limit) {
    const RayProxy& proxy = tree.proxies[slot];
    std::optional<QueryHit> hit;
    if (proxy.closedForm) {
      if (!passes(proxy.filter, filter)) return;
      // As rayBody does for a body of one shape, from the copy.
      const Mat3& R = proxy.rotation;
      const std::optional<RayHit> local =
          rayCast(proxy.shape, R.transpose() * (origin - proxy.position), R.transpose() * d, limit);
      if (!local) return;
      hit = QueryHit{};
      hit->distance = local->fraction;
      hit->normal = R * local->normal;
      hit->point = origin + hit->distance * d;
    } else {
      hit = rayBody(world.bodies()[i], origin, d, limit, filter);
    }
    if (hit) {
      if (best && hit->distance >= best->distance) return;
      nameBody(world, i, *hit);
      limit = hit->distance;
      best = hit;
    }
  });
  if (planePasses(filter)) {
    for (std::size_t k = 0; k < world.planes().size(); ++k) {
      std::optional<QueryHit> hit = rayPlane(world.planes()[k], origin, d, reach);
      if (hit && (!best || hit->distance <= best->distance)) {
        hit->plane = k;
        reach = hit->distance;
        best = hit;
      }
    }
  }
  return best;
}

// The query shape as an engine Shape (whose factories check the sizes) and its pose.
struct PosedQueryShape {
  Shape shape;
  Mat3 rotation;
  Vec3 position;
};
PosedQueryShape posedQueryShape(const std::string& call, const QueryShape& q) {
  checkFinitePoint(call, "shape position", q.position);
  const double norm = q.orientation.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > kRotationTolerance) {
    throw std::invalid_argument(call + ": expected a unit shape orientation");
  }
  try {
    switch (q.kind) {
      case QueryShape::Kind::Sphere: return {Shape::sphere(q.radius), Mat3::Identity(), q.position};
      case QueryShape::Kind::Box: return {Shape::box(q.halfExtents), q.orientation.toRotationMatrix(), q.position};
      case QueryShape::Kind::Capsule:
        return {Shape::capsule(q.radius, q.halfLength), q.orientation.toRotationMatrix(), q.position};
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(call + ": shape: " + e.what());
  }
  throw std::invalid_argument(call + ": unknown shape kind");
}

Aabb queryShapeBounds(const PosedQueryShape& p) {
  const auto [lo, hi] = p.shape.worldBounds(p.rotation, p.position);
  return {lo, hi};
}

}  // namespace

QueryShape QueryShape::sphere(double radius, const Vec3& position) {
  QueryShape q;
  q.kind = Kind::Sphere;
  q.radius = radius;
  q.position = position;
  return q;
}

QueryShape QueryShape::box(const Vec3& halfExtents, const Vec3& position, const Quat& orientation) {
  QueryShape q;
  q.kind = Kind::Box;
  q.halfExtents = halfExtents;
  q.position = position;
  q.orientation = orientation;
  return q;
}

QueryShape QueryShape::capsule(double radius, double halfLength, const Vec3& position, const Quat& orientation) {
  QueryShape q;
  q.kind = Kind::Capsule;
  q.radius = radius;
  q.halfLength = halfLength;
  q.position = position;
  q.orientation = orientation;
  return q;
}

std::optional<QueryHit> castRay(const World& world, const Vec3& origin, const Vec3& direction, double maxDistance,
                                const QueryFilter& filter) {
  const Vec3 d = checkedCastDirection("castRay", direction, maxDistance);
  checkFinitePoint("castRay", "origin", origin);
  return castOneRay(world, *queryTree(world), origin, d, maxDistance, filter);
}

std::vector<std::optional<QueryHit>> castRays(const World& world, const std::vector<Vec3>& origins,
                                              const std::vector<Vec3>& directions, double maxDistance,
                                              const QueryFilter& filter) {
  if (origins.size() != directions.size()) {
    throw std::invalid_argument("castRays: " + std::to_string(origins.size()) + " origins but " +
                                std::to_string(directions.size()) + " directions");
  }
  std::vector<Vec3> unit(directions.size());
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const std::string call = "castRays: ray " + std::to_string(i);
    unit[i] = checkedCastDirection(call, directions[i], maxDistance);
    checkFinitePoint(call, "origin", origins[i]);
  }
  const std::shared_ptr<const QueryTree> tree = queryTree(world);
  std::vector<std::optional<QueryHit>> hits(origins.size());
  for (std::size_t i = 0; i < origins.size(); ++i) hits[i] = castOneRay(world, *tree, origins[i], unit[i], maxDistance, filter);
  return hits;
}

std::optional<QueryHit> castShape(const World& world, const QueryShape& shape, const Vec3& direction,
                                  double maxDistance, const QueryFilter& filter) {
  const Vec3 d = checkedCastDirection("castShape", direction, maxDistance);
  const PosedQueryShape p = posedQueryShape("castShape", shape);
  const Aabb start = queryShapeBounds(p);
  // The centre's ray against every box grown by the shape's half extents: the swept box's walk.
  const Vec3 grow = 0.5 * start.extents(), centre = start.centre();
  std::optional<QueryHit> best;
  double reach = maxDistance;
  queryTree(world)->walkRay(centre, d, reach, grow, [&](std::uint32_t i, std::uint32_t, double& limit) {
    std::optional<QueryHit> hit = castBody(world.bodies()[i], p.shape, p.rotation, p.position, d, limit, filter);
    if (hit && (!best || hit->distance < best->distance)) {
      nameBody(world, i, *hit);
      limit = hit->distance;
      best = hit;
    }
  });
  if (planePasses(filter)) {
    for (std::size_t k = 0; k < world.planes().size(); ++k) {
      std::optional<QueryHit> hit = castPlane(world.planes()[k], p.shape, p.rotation, p.position, d, reach);
      if (hit && (!best || hit->distance < best->distance)) {
        hit->plane = k;
        reach = hit->distance;
        best = hit;
      }
    }
  }
  return best;
}

std::vector<QueryHit> overlapShape(const World& world, const QueryShape& shape, const QueryFilter& filter) {
  const PosedQueryShape p = posedQueryShape("overlapShape", shape);
  std::vector<std::pair<std::uint32_t, QueryHit>> bodies;
  queryTree(world)->walkBox(queryShapeBounds(p), [&](std::uint32_t i) {
    if (std::optional<QueryHit> hit = overlapBody(world.bodies()[i], p.shape, p.rotation, p.position, filter)) {
      bodies.emplace_back(i, *hit);
    }
  });
  std::sort(bodies.begin(), bodies.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<QueryHit> found;
  for (auto& [i, hit] : bodies) {
    nameBody(world, i, hit);
    found.push_back(hit);
  }
  if (planePasses(filter)) {
    for (std::size_t k = 0; k < world.planes().size(); ++k) {
      if (!overlapsPlane(world.planes()[k], p.shape, p.rotation, p.position)) continue;
      QueryHit hit;
      hit.isPlane = true;
      hit.plane = k;
      hit.normal = world.planes()[k].normal;
      found.push_back(hit);
    }
  }
  return found;
}

std::optional<QueryHit> closestPoint(const World& world, const Vec3& point, double maxDistance,
                                     const QueryFilter& filter) {
  checkFinitePoint("closestPoint", "point", point);
  if (!(maxDistance >= 0.0)) throw std::invalid_argument("closestPoint: expected a max distance >= 0");
  std::optional<QueryHit> best;
  double bound = maxDistance;  // shrinks to the nearest surface so far
  const auto better = [&](const QueryHit& hit) { return hit.distance <= bound && (!best || hit.distance < best->distance); };
  queryTree(world)->walkNearest(point, bound, [&](std::uint32_t i, double& limit) {
    std::optional<QueryHit> hit = closestOnBody(world.bodies()[i], point, filter);
    if (hit && better(*hit)) {
      nameBody(world, i, *hit);
      limit = hit->distance;
      best = hit;
    }
  });
  if (planePasses(filter)) {
    for (std::size_t k = 0; k < world.planes().size(); ++k) {
      QueryHit hit = closestOnPlane(world.planes()[k], point);
      if (better(hit)) {
        hit.plane = k;
        bound = hit.distance;
        best = hit;
      }
    }
  }
  return best;
}

std::vector<BodyId> queryAabb(const World& world, const Aabb& box, const QueryFilter& filter) {
  if (box.min.hasNaN() || box.max.hasNaN()) throw std::invalid_argument("queryAabb: expected a box without NaN");
  std::vector<std::uint32_t> indices;
  queryTree(world)->walkBox(box, [&](std::uint32_t i) {
    if (anyShapePasses(world.bodies()[i], filter)) indices.push_back(i);
  });
  std::sort(indices.begin(), indices.end());
  std::vector<BodyId> ids;
  ids.reserve(indices.size());
  for (const std::uint32_t i : indices) ids.push_back(world.idAt(i));
  return ids;
}

}  // namespace rbsim
