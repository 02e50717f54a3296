#include "rbsim/world/queries.h"

#include "collision/broadphase/brute_force.h"
#include "collision/narrowphase/convex_convex.h"
#include "rbsim/world/world.h"

namespace rbsim {

std::vector<ProxyPair> bruteForcePairs(const World& world) {
  const CollisionPipeline& collision = world.collision();
  BruteForce brute;
  for (std::size_t i = 0; i < collision.boxes().size(); ++i) brute.add(collision.boxes()[i], world.bodies()[i].isStatic());
  brute.update();
  return brute.pairs();
}

BodyDistance bodyDistance(const World& world, BodyId a, BodyId b) {
  const ConvexDistance d = convexDistance(world.body(a).worldVertices(), world.body(b).worldVertices());
  return {d.overlap, d.distance, d.pointA, d.pointB};
}

}  // namespace rbsim
