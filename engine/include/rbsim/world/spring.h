#pragma once
// A damped spring from a world anchor to a point fixed in a body (seed 000 "particle systems":
// spring forces F = -k (|d| - rest) d/|d| - c v_rel along d). Accumulated each step with gravity.
#include <cstddef>
#include <utility>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/math/types.h"

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
// Adds one on a dynamic body; returns its index in springs(world). Throws std::invalid_argument on
// a stale id, a static or kinematic body, or an anchor, point, stiffness, rest length or damping
// that is not finite and >= 0.
std::size_t addSpring(World& world, const Spring& spring);
const std::vector<Spring>& springs(const World& world);
// A spring whose anchor is moved by hand (window mode drags a body by one, as Box2D's mouse
// joint): wakes the body, as every manual change does. Throws on a bad index or anchor.
void moveSpringAnchor(World& world, std::size_t spring, const Vec3& anchor);
void removeSpring(World& world, std::size_t spring);  // later springs move down one index

}  // namespace rbsim
