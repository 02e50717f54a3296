#pragma once
// Seed 000 "Friction" for one contact point inside a sweep of accumulated impulses (Catto,
// "Iterative Dynamics with Temporal Coherence", GDC 2005): Settings::FrictionModel::Seed000.
// The point's normal row has just been solved; with its accumulated j_n, the tangential impulse
// is seed 000's, through the tangential block K_TT of the point's K_T = K_1 + K_2:
//   sticking: j_T = j_T,acc - K_TT^-1 u_rel,T (u_rel,T^new = 0), kept if |j_T| <= mu_s j_n;
//   sliding:  j_T = -mu_k j_n T with T = u_rel,T / |u_rel,T|.
// Sweeping the normal and tangential rows in turn converges to the point where both of seed 000's
// conditions hold at once, which is what its 3x3 solve finds for an isolated collision.
//
// Seed 000 decides for one isolated collision. In a sweep the first point visited takes the
// body's whole load alone, and its static impulse leaves the cone where the patch's would not. So
// the kinetic branch is taken by a point that ended the last step sliding (`sliding`); a point
// that ended it sticking, or is new, keeps static friction through the step, limited to the mu_s
// cone's edge against the impending slip, and slides from the next step if it then ends the step
// slipping. Measured without this rule, and with the normal and tangential impulse solved together
// through the full 3x3 K_T at each visit: a box at rest on a 25 degree incline (mu_s 0.6, mu_k 0.5)
// slid 7 cm in 10 s, and on a 28 degree one it accelerated from the first step, every point gone
// kinetic and none able to come back (REPORT section 5).
#include "rbsim/math/types.h"

namespace rbsim {

// A point whose tangential slip at the end of a step is above this slides in the next (the scale
// of Box2D's b2_linearSleepTolerance, as the cone model's kStickingSlipSpeed).
inline constexpr double kSeedSlidingSpeed = 0.01;  // [m/s]

struct SeedFriction {
  Vec3 total = Vec3::Zero();  // the new accumulated tangential impulse on body 1, world [N s]
  bool sticking = false;      // the sticking impulse was inside the mu_s cone
};

// `totalFactor` is K_T at the point, `relativeVelocity` u_1 - u_2 there now (every impulse so far
// applied), t1, t2 the unit tangents completing the normal N towards body 1,
// `accumulated` the tangential impulse applied so far this step and `normalImpulse` the point's
// accumulated j_n >= 0 [N s].
SeedFriction seedFriction(const Mat3& totalFactor, const Vec3& relativeVelocity, const Vec3& t1, const Vec3& t2,
                          const Vec3& accumulated, double normalImpulse, double staticFriction,
                          double kineticFriction, bool sliding);

}  // namespace rbsim
