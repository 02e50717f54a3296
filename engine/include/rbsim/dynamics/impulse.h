#pragma once
// Impulses on rigid bodies (seed 000 "Collision Response", "Friction"; seed 002 2.2.1-2.2.2).
// An impulse j at the point x + r changes P by j and L by r x j; the velocity of that point then
// changes by K j, with K the impulse factor below. Static bodies and planes have K = 0.
#include <type_traits>

#include <Eigen/Core>

#include "rbsim/body/material.h"
#include "rbsim/math/types.h"

namespace rbsim {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// K = (1/M) 1 + r*^T I^-1 r* (seed 000 "Collision Response"; seed 002's K~, the top-left block).
Mat3 impulseFactor(double inverseMass, const Mat3& inverseInertiaWorld, const Vec3& r);

// Seed 002 2.2.1: the 6x6 factor mapping a linear and angular impulse (j, j_tau) at x + r to the
// change of that point's velocity and of the angular velocity: (dv_r, domega) = K (j, j_tau).
Mat6 coupledImpulseFactor(double inverseMass, const Mat3& inverseInertiaWorld, const Vec3& r);

// Seed 002's 6x6 K restricted to friction coordinates: S^T K S with S = [(t1, 0), (t2, 0), (0, n)]
// (tangential impulses along t1, t2 and an angular impulse about n), formed without the 6x6
// product: the contact solver builds one per manifold per step. t1, t2, n orthonormal.
Mat3 frictionImpulseFactor(double inverseMass, const Mat3& inverseInertiaWorld, const Vec3& r, const Vec3& t1,
                           const Vec3& t2, const Vec3& n);

// The result of collisionImpulse, in 3D or (for engine/planar) in 2D.
template <int Dim>
struct CollisionImpulseIn {
  Eigen::Matrix<double, Dim, 1> impulse = Eigen::Matrix<double, Dim, 1>::Zero();  // on body 1; body 2 gets -j [N s]
  bool colliding = false;  // u_rel,N < 0: the bodies were approaching
  bool sticking = false;   // the static-friction impulse was inside the friction cone
};
using CollisionImpulse = CollisionImpulseIn<3>;

// One contact, solved exactly as seed 000 derives it: no impulse unless u_rel,N < 0; first the
// sticking impulse j = K_T^-1 (-c_R u_rel,N N - u_rel), kept if |j - (j.N)N| <= mu_s (j.N);
// otherwise the kinetic impulse j = (N - mu_k T) j_n with T = u_rel,T / |u_rel,T| and
// -c_R u_rel,N = u_rel,N + N^T K_T (N - mu_k T) j_n. `relativeVelocity` is u_1 - u_2 at the
// point, `normal` the unit normal pointing towards body 1, `totalFactor` K_T = K_1 + K_2. The same
// algorithm in 2D (Dim = 2) serves the planar bodies of seed 002 section 2.
// (The dimension is taken from K alone, so the vectors may be Eigen expressions.)
template <int Dim>
using ImpulseVector = typename std::enable_if<true, Eigen::Matrix<double, Dim, 1>>::type;
template <int Dim>
CollisionImpulseIn<Dim> collisionImpulse(const Eigen::Matrix<double, Dim, Dim>& totalFactor,
                                         const ImpulseVector<Dim>& relativeVelocity, const ImpulseVector<Dim>& normal,
                                         const Material& material);
extern template CollisionImpulseIn<2> collisionImpulse<2>(const Eigen::Matrix2d&, const ImpulseVector<2>&,
                                                          const ImpulseVector<2>&, const Material&);
extern template CollisionImpulseIn<3> collisionImpulse<3>(const Eigen::Matrix3d&, const ImpulseVector<3>&,
                                                          const ImpulseVector<3>&, const Material&);

}  // namespace rbsim
