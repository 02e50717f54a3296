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
  for (const ScriptedForce& f : scriptedForces(world)) {
    if (f.body == body && isActive(f, t)) active.push_back(inWorldFrame(f, b));
  }
  return active;
}

const Material& bodyMaterial(const World& world, BodyId body) {
  return WorldAccess::bodyMaterials(world)[world.indexOf(body)];
}

const Material& planeMaterial(const World& world, std::size_t plane) { return WorldAccess::planeMaterials(world).at(plane); }
const std::vector<BodySolid>& bodySolids(const World& world) { return WorldAccess::bodySolids(world); }
const std::vector<FractureEvent>& fractureEvents(const World& world) { return WorldAccess::fractureEvents(world); }
const std::vector<ScriptedForce>& scriptedForces(const World& world) { return WorldAccess::forces(world); }
std::size_t recycledContacts(const World& world) { return WorldAccess::collision(world).recycledCount(); }
std::uint64_t geometryVersion(const World& world) { return WorldAccess::geometryVersion(world); }
// Declared in world/contact_events.h, beside the events it returns.
const ContactEvents& contactEvents(const World& world) { return WorldAccess::contactEvents(world).events(); }

BodyDistance bodyDistance(const World& world, BodyId a, BodyId b) {
  const ConvexDistance d = convexDistance(world.body(a).worldVertices(), world.body(b).worldVertices());
  return {d.overlap, d.distance, d.pointA, d.pointB};
}

}  // namespace rbsim
