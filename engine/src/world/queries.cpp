#include "rbsim/world/queries.h"

#include <algorithm>

#include "collision/broadphase/brute_force.h"
#include "collision/narrowphase/convex_convex.h"
#include "world/world_access.h"

namespace rbsim {

const std::vector<ProxyPair>& candidatePairs(const World& world) {
  return WorldAccess::collision(world).candidatePairs();
}

const std::vector<Aabb>& broadPhaseBoxes(const World& world) { return WorldAccess::collision(world).boxes(); }

const std::vector<Impact>& impacts(const World& world) { return WorldAccess::collision(world).impacts(); }

std::vector<ProxyPair> bruteForcePairs(const World& world) {
  const CollisionPipeline& collision = WorldAccess::collision(world);
  BruteForce brute;
  for (std::size_t i = 0; i < collision.boxes().size(); ++i) brute.add(collision.boxes()[i], world.bodies()[i].isStatic());
  brute.update();
  return brute.pairs();
}

std::size_t awakeCount(const World& world) {
  const std::vector<RigidBody>& bodies = world.bodies();
  return static_cast<std::size_t>(std::count_if(bodies.begin(), bodies.end(), [](const RigidBody& b) { return b.awake(); }));
}

std::vector<std::pair<Vec3, Vec3>> activeForces(const World& world, BodyId body, double t) {
  std::vector<std::pair<Vec3, Vec3>> active;
  const RigidBody& b = world.body(body);
  for (const ScriptedForce& f : world.scriptedForces()) {
    if (f.body == body && isActive(f, t)) active.push_back(inWorldFrame(f, b));
  }
  return active;
}

BodyDistance bodyDistance(const World& world, BodyId a, BodyId b) {
  const ConvexDistance d = convexDistance(world.body(a).worldVertices(), world.body(b).worldVertices());
  return {d.overlap, d.distance, d.pointA, d.pointB};
}

}  // namespace rbsim
