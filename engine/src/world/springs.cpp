// A World's springs (world/spring.h: addSpring, springs, moveSpringAnchor, removeSpring), free
// functions over World (docs/architecture.md, "The World's surface").
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rbsim/world/spring.h"
#include "world/world_access.h"

namespace rbsim {

SpringId addSpring(World& world, const Spring& spring) {
  if (!world.isValid(spring.body)) throw std::invalid_argument("spring names no body");
  const RigidBody& body = std::as_const(world).body(spring.body);
  if (!body.isDynamic()) throw std::invalid_argument("spring on the static or kinematic body '" + body.name() + "'");
  if (!spring.anchor.allFinite() || !spring.point.allFinite() || !(spring.stiffness >= 0.0) || !(spring.restLength >= 0.0) ||
      !(spring.damping >= 0.0) || !std::isfinite(spring.stiffness) || !std::isfinite(spring.restLength) ||
      !std::isfinite(spring.damping)) {
    throw std::invalid_argument("spring on body '" + body.name() + "': expected finite anchor and point, k, rest length and damping >= 0");
  }
  WorldAccess::springs(world).push_back(spring);
  return WorldAccess::springIds(world).add();
}

const std::vector<Spring>& springs(const World& world) { return WorldAccess::springs(world); }

bool isValid(const World& world, SpringId spring) { return WorldAccess::springIds(world).isValid(spring); }

namespace {

// The spring's index, or std::invalid_argument naming the call.
std::size_t checkedIndex(const World& world, SpringId spring, const char* call) {
  if (!isValid(world, spring)) {
    throw std::invalid_argument(std::string(call) + ": spring id (slot " + std::to_string(spring.slot) + ", generation " +
                                std::to_string(spring.generation) + ") is stale: the spring was removed, or never made here");
  }
  return WorldAccess::springIds(world).indexOf(spring);
}

}  // namespace

std::size_t indexOf(const World& world, SpringId spring) { return checkedIndex(world, spring, "indexOf"); }

SpringId springIdAt(const World& world, std::size_t index) {
  if (index >= springs(world).size()) throw std::invalid_argument("springIdAt: no spring at index " + std::to_string(index));
  return WorldAccess::springIds(world).idAt(index);
}

void moveSpringAnchor(World& world, SpringId spring, const Vec3& anchor) {
  const std::size_t index = checkedIndex(world, spring, "moveSpringAnchor");
  if (!anchor.allFinite()) throw std::invalid_argument("moveSpringAnchor: expected a finite anchor");
  Spring& s = WorldAccess::springs(world)[index];
  s.anchor = anchor;
  WorldAccess::wakeBody(world, world.indexOf(s.body));  // and lists it awake
}

void removeSpring(World& world, SpringId spring) {
  const std::size_t index = checkedIndex(world, spring, "removeSpring");
  WorldAccess::springIds(world).eraseAt(WorldAccess::springs(world), index);
}

Spring dragSpring(BodyId id, const RigidBody& body, const Vec3& worldPoint) {
  Spring spring;
  spring.body = id;
  spring.anchor = worldPoint;
  spring.point = body.rotation().transpose() * (worldPoint - body.position());
  spring.stiffness = kDragStiffnessPerKg * body.mass();
  spring.damping = kDragDampingRatio * 2.0 * std::sqrt(spring.stiffness * body.mass());
  return spring;
}

}  // namespace rbsim
