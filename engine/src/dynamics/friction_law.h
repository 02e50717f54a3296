#pragma once
// Friction at one contact point inside a sweep of accumulated impulses (Catto, "Iterative
// Dynamics with Temporal Coherence", GDC 2005): the rule Settings::FrictionModel names, written
// once for both solvers. The point's normal row has just been solved; from its accumulated j_n,
// the slip u_rel,T now and the tangential impulse so far, the law returns the new accumulated
// tangential impulse, in the point's tangent basis (t1, t2).
//
// Cone (the default): per tangent, the impulse that stops the slip along it, 1 / (t_k^T K_T t_k)
// (Box2D v3's two friction rows), then scaled onto the cone mu j_n, mu = mu_s while the regime
// sticks and mu_k while it slides.
//
// Seed000 (seed 000 "Friction"), through the tangential block K_TT of K_T = K_1 + K_2:
//   sticking: j_T = j_T,acc - K_TT^-1 u_rel,T (u_rel,T^new = 0), kept if |j_T| <= mu_s j_n;
//   sliding:  j_T = -mu_k j_n T with T = u_rel,T / |u_rel,T|.
// Sweeping the normal and tangential rows in turn converges to the point where both of seed 000's
// conditions hold at once, which is what its 3x3 solve finds for an isolated collision.
// Seed 000 decides for one isolated collision. In a sweep the first point visited takes the
// body's whole load alone, and its static impulse leaves the cone where the patch's would not. So
// the kinetic branch is taken by a point that ended the last step sliding (`sliding`); a point
// that ended it sticking, or is new, keeps static friction through the step, limited to the mu_s
// cone's edge against the impending slip, and slides from the next step if it then ends the step
// slipping. Measured without this rule, and with the normal and tangential impulse solved together
// through the full 3x3 K_T at each visit: a box at rest on a 25 degree incline (mu_s 0.6, mu_k 0.5)
// slid 7 cm in 10 s, and on a 28 degree one it accelerated from the first step, every point gone
// kinetic and none able to come back (REPORT section 5).
//
// The PGS solver applies the cone to a manifold as a whole instead (pgs_solver.h), at its
// centroid with a twist: a rigid patch slides as a whole there.
#include <cmath>

#include <Eigen/Core>

#include "rbsim/settings/settings.h"

namespace rbsim {

// A contact that ends a step slipping faster than this slides (mu_k) in the next; slower, it
// sticks (mu_s). The scale of Box2D's b2_linearSleepTolerance: a contact that slow is at rest for
// every purpose a user sees.
inline constexpr double kSlidingSpeed = 0.01;  // [m/s]

// One point as the law reads it; vectors in the tangent basis (t1, t2) that completes the normal
// N towards body 1, on which the impulse acts (body 2 takes its opposite).
struct FrictionPoint {
  Eigen::Vector2d accumulated = Eigen::Vector2d::Zero();  // tangential impulse so far this step [N s]
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();         // u_rel,T = u_1 - u_2 now [m/s]
  Eigen::Vector2d tangentMass = Eigen::Vector2d::Zero();  // 1 / (t_k^T K_T t_k) [kg]
  double coupling = 0.0;       // t1^T K_T t2: with the masses, the whole K_TT [1/kg]
  double normalImpulse = 0.0;  // accumulated j_n >= 0 [N s]
  double staticFriction = 0.0, kineticFriction = 0.0;  // mu_s, mu_k [1]
  bool sliding = false;  // the regime: this contact ended the last step slipping
};

struct FrictionImpulse {
  Eigen::Vector2d total = Eigen::Vector2d::Zero();  // the new accumulated tangential impulse [N s]
  bool sticking = false;  // the impulse that stops the slip was inside the static cone
};

// The cone, inline: it runs for every point of every sweep.
inline FrictionImpulse coneFriction(const FrictionPoint& p) {
  FrictionImpulse out;
  out.total = p.accumulated - p.tangentMass.cwiseProduct(p.slip);
  const double limit = (p.sliding ? p.kineticFriction : p.staticFriction) * p.normalImpulse;
  const double squared = out.total.squaredNorm();
  out.sticking = squared <= limit * limit;
  // A point that does not push has no friction: the common case of a speculative point, spared
  // the square root and the division on the sweep's chain.
  if (!out.sticking) {
    out.total = limit == 0.0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(out.total * (limit / std::sqrt(squared)));
  }
  return out;
}

FrictionImpulse seed000Friction(const FrictionPoint& p);  // friction_law.cpp

inline FrictionImpulse frictionImpulse(Settings::FrictionModel model, const FrictionPoint& point) {
  return model == Settings::FrictionModel::Seed000 ? seed000Friction(point) : coneFriction(point);
}

}  // namespace rbsim
