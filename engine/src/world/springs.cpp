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

std::size_t addSpring(World& world, const Spring& spring) {
  if (!world.isValid(spring.body)) throw std::invalid_argument("spring names no body");
  const RigidBody& body = std::as_const(world).body(spring.body);
  if (!body.isDynamic()) throw std::invalid_argument("spring on the static or kinematic body '" + body.name() + "'");
  if (!spring.anchor.allFinite() || !spring.point.allFinite() || !(spring.stiffness >= 0.0) || !(spring.restLength >= 0.0) ||
      !(spring.damping >= 0.0) || !std::isfinite(spring.stiffness) || !std::isfinite(spring.restLength) ||
      !std::isfinite(spring.damping)) {
    throw std::invalid_argument("spring on body '" + body.name() + "': expected finite anchor and point, k, rest length and damping >= 0");
  }
  std::vector<Spring>& springs = WorldAccess::springs(world);
  springs.push_back(spring);
  return springs.size() - 1;
}

const std::vector<Spring>& springs(const World& world) { return WorldAccess::springs(world); }

void moveSpringAnchor(World& world, std::size_t spring, const Vec3& anchor) {
  std::vector<Spring>& springs = WorldAccess::springs(world);
  if (spring >= springs.size()) throw std::invalid_argument("moveSpringAnchor: no such spring");
  if (!anchor.allFinite()) throw std::invalid_argument("moveSpringAnchor: expected a finite anchor");
  springs[spring].anchor = anchor;
  WorldAccess::wakeBody(world, world.indexOf(springs[spring].body));  // and lists it awake
}

void removeSpring(World& world, std::size_t spring) {
  std::vector<Spring>& springs = WorldAccess::springs(world);
  if (spring >= springs.size()) throw std::invalid_argument("removeSpring: no such spring");
  springs.erase(springs.begin() + static_cast<std::ptrdiff_t>(spring));
}

}  // namespace rbsim
