#pragma once
// The state vector Y(t) of seed 004 "Rigid body representation" / seed 000 "state vector":
// position, orientation, linear and angular momentum. Kept apart from the constants and the
// geometry (Box2D's b2BodyState) so integrators read and write only this.
#include "rbsim/math/types.h"

namespace rbsim {

struct BodyState {
  Vec3 position = Vec3::Zero();         // x(t) [m]
  Quat orientation = Quat::Identity();  // q(t), unit; R(t) is derived from it
  Vec3 linearMomentum = Vec3::Zero();   // P(t) = m v [kg m/s]
  Vec3 angularMomentum = Vec3::Zero();  // L(t) = I(t) omega, world frame [kg m^2/s]
};
// 112 bytes, 1.75 cache lines of 64: x (24), 8 of padding that aligns q to 16 for Eigen's
// vectorised quaternion product, q (32), P and L (24 each). RigidBody's hot part holds it
// (rigid_body.h), and the undo record keeps one per body each step.
static_assert(!kStatedLayout || sizeof(BodyState) == 112, "BodyState's size: see the comment above");

// Every component finite: a state a step may commit (World's divergence check).
inline bool isFinite(const BodyState& s) {
  return s.position.allFinite() && s.orientation.coeffs().allFinite() && s.linearMomentum.allFinite() &&
         s.angularMomentum.allFinite();
}

}  // namespace rbsim
