#pragma once
// A damped spring from a world anchor to a point fixed in a body (seed 000 "particle systems":
// spring forces F = -k (|d| - rest) d/|d| - c v_rel along d). Accumulated each step with gravity.
#include <cstddef>
#include <utility>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/math/types.h"
#include "rbsim/world/item_ids.h"

namespace rbsim {

class World;

struct Spring {
  BodyId body;
  Vec3 anchor = Vec3::Zero();      // world frame [m]
  Vec3 point = Vec3::Zero();       // body frame, relative to the centre of mass [m]
  double stiffness = 0.0;          // k [N/m], >= 0
  double restLength = 0.0;         // [m], >= 0
  double damping = 0.0;            // c [N s/m], >= 0, along the spring only
};

// Seed 000 "particle systems" spring: F = -(k (|d| - rest) + c v_p . u) u at the body point p,
// d = p - anchor, u = d / |d|, as (point, force) in world frame for the body's pose now: what
// stage AccumulateForces applies. For rest = 0, F = -k d - c (v_p . u) u needs no direction when
// d = 0, so a zero-length spring is well defined; for rest > 0 and d = 0 there is no direction.
std::pair<Vec3, Vec3> forceOfSpring(const Spring& spring, const RigidBody& body);

// A World's springs, free functions over World (docs/architecture.md, "The World's surface").
// Adds one on a dynamic body; returns its id (world/item_ids.h), which names the spring until it
// is removed, by hand or with its body. Throws std::invalid_argument on a stale body id, a static
// or kinematic body, or an anchor, point, stiffness, rest length or damping that is not finite
// and >= 0.
SpringId addSpring(World& world, const Spring& spring);
const std::vector<Spring>& springs(const World& world);
// A spring's id and its index in springs(world): false / throws std::invalid_argument for a stale
// id (the spring removed, or never made here); springIdAt throws when out of range.
bool isValid(const World& world, SpringId spring);
std::size_t indexOf(const World& world, SpringId spring);
SpringId springIdAt(const World& world, std::size_t index);
// A spring whose anchor is moved by hand (window mode drags a body by one, as Box2D's mouse
// joint): wakes the body, as every manual change does. Throws on a stale id or a bad anchor,
// the World unchanged.
void moveSpringAnchor(World& world, SpringId spring, const Vec3& anchor);
// Its id goes stale; later springs move down one index in springs(world), their ids unchanged.
// Throws on a stale id, the World unchanged.
void removeSpring(World& world, SpringId spring);

// The drag of a pointer (window mode, the browser's pages): a damped spring from the pointer to
// the grabbed point (seed 000's spring, as Box2D's mouse joint), its stiffness per kilogram, so
// every body follows at the same angular frequency sqrt(k/m) = 7 rad/s, damped at 0.7 of critical.
inline constexpr double kDragStiffnessPerKg = 50.0;  // [N/(m kg)]
inline constexpr double kDragDampingRatio = 0.7;     // [1] of critical damping 2 sqrt(k m)
// That spring on body `id` (`body` is its RigidBody) grabbed at `worldPoint`, anchored there.
Spring dragSpring(BodyId id, const RigidBody& body, const Vec3& worldPoint);

}  // namespace rbsim
