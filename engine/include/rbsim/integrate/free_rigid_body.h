#pragma once
// The exact torque-free motion of a rigid body, evaluated in closed form: the body-frame angular
// momentum by Jacobi elliptic functions and the rotation about L by an incomplete elliptic
// integral of the third kind (Landau & Lifshitz, Mechanics §37; Celledoni, Fasso, Safstrom,
// Zanna, "The exact computation of the free rigid body motion and its use in splitting methods",
// SIAM J. Sci. Comput. 30, 2008). Boost.Math evaluates the special functions.
//
// Every regime: rotation on either side of the separatrix, on it, symmetric bodies, a sphere-like
// inertia, spins about a principal axis (steady) and rest. The motion is computed from the state
// at an epoch, so a run of steps accumulates no error: step n evaluates the flow at n dt.
#include "rbsim/math/types.h"

namespace rbsim {

class FreeRigidBodyFlow {
 public:
  // principalToWorld: the rotation from the principal frame to the world at the epoch;
  // angularMomentum: L in the world frame [kg m^2/s]; principalMoments: I_1..3 > 0 [kg m^2],
  // in any order.
  FreeRigidBodyFlow(const Quat& principalToWorld, const Vec3& angularMomentum, const Vec3& principalMoments);

  // The principal frame's orientation t [s] after the epoch (t may be negative: the flow is
  // reversible), unit to rounding (not renormalised). L stays what it was: the flow maps the
  // body-frame momentum onto it exactly.
  Quat principalToWorld(double t) const;
  // The angular momentum in the principal frame at time t [kg m^2/s].
  Vec3 principalMomentum(double t) const;

  const Quat& epochOrientation() const { return epoch_; }
  // principalToWorld as given to the constructor (epoch_ is it normalised): a World snapshot
  // (world/world_snapshot.h) builds the same flow again from it, bit for bit.
  const Quat& givenOrientation() const { return given_; }
  const Vec3& angularMomentum() const { return angularMomentum_; }
  const Vec3& principalMoments() const { return moments_; }
  // The elliptic modulus k in [0, 1] (1 on the separatrix) and the period of the body-frame
  // momentum [s] (infinite for a steady spin, at rest and on the separatrix).
  double modulus() const { return k_; }
  double period() const;

 private:
  enum class Regime { Rest, Steady, Elliptic };
  struct Phase {
    Vec3 momentum;  // m(u) in the circulation frame
    double pi;      // Pi(n; am u | k), continuous in u
  };
  Phase phaseAt(double u) const;
  double rotationAboutMomentum(const Phase& phase, double t) const;  // phi(t) - phi(0) [rad]

  Quat given_;
  Quat epoch_;              // principal -> world at t = 0
  Vec3 angularMomentum_;    // L, world [kg m^2/s]
  Vec3 moments_;            // as given
  Regime regime_ = Regime::Rest;
  Vec3 steadyOmega_ = Vec3::Zero();  // world omega of a steady spin [rad/s]

  // The circulation frame c: a signed permutation of the principal axes (a rotation) whose third
  // axis is the one the momentum circulates about, with m_3 >= 0.
  // R(t) = epochFrame_ Rz(phi(t) - phi(0)) A(m(t)) principalToCirculation_, with
  // epochFrame_ = R_c(0) A(m(0))^-1 and A(m) the rotation taking m / |m| to e_3.
  Quat epochFrame_;
  Quat principalToCirculation_;
  Mat3 circulationFromPrincipal_;
  Vec3 circulationMoments_;  // I in the circulation frame [kg m^2]
  double momentumMagnitude_ = 0.0;  // G = |L| [kg m^2/s]
  Vec3 amplitudes_ = Vec3::Zero();  // a1, a2, a3 >= 0: m = (a1 cn u, a2 sn u, a3 dn u)
  double k_ = 0.0;                  // modulus
  double complementary2_ = 1.0;     // kc^2 = 1 - k^2, computed apart: it carries the digits
  double rate_ = 0.0;               // lambda = du/dt [1/s], signed
  double u0_ = 0.0;                 // u at t = 0
  double quarterPeriodK_ = 0.0;     // K(k), infinite at k = 1
  double characteristic_ = 0.0;     // n = -a3^2 k^2 / a1^2 of Pi(n; am | k)
  double completePi_ = 0.0;         // Pi(n | k), infinite at k = 1
  double pi0_ = 0.0;                // Pi(n; am(u0) | k)
  double precessionRate_ = 0.0;     // G / I_3c [rad/s]
  double piCoefficient_ = 0.0;      // G (1/I_1c - 1/I_3c) / lambda [1]
};

}  // namespace rbsim
