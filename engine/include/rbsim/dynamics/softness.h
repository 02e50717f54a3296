#pragma once
// A soft constraint: the constraint C = 0 held by a spring of natural frequency f and damping
// ratio zeta, integrated implicitly over a substep h (Catto, "Soft Constraints", GDC 2011;
// Box2D v3's b2MakeSoft). With omega = 2 pi f, stiffness k = m omega^2 and damping c = 2 m zeta
// omega, the implicit update of the constraint velocity gives
//   lambda = -m_eff (massScale (Jv) + biasRate C) - impulseScale lambda_acc,
//   biasRate = omega / (2 zeta + h omega),
//   massScale = h omega (2 zeta + h omega) / (1 + h omega (2 zeta + h omega)),
//   impulseScale = 1 / (1 + h omega (2 zeta + h omega)).
// f = 0 is a rigid constraint that never corrects position: bias 0, massScale 1, impulseScale 0.
#include <cmath>

#include "rbsim/math/types.h"

namespace rbsim {

struct Softness {
  double biasRate = 0.0;      // [1/s]: velocity asked per metre of error
  double massScale = 1.0;     // [1]
  double impulseScale = 0.0;  // [1]
};

inline Softness makeSoftness(double hertz, double dampingRatio, double h) {
  if (hertz == 0.0) return {};
  const double omega = 2.0 * kPi * hertz;
  const double a1 = 2.0 * dampingRatio + h * omega;
  const double a2 = h * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

}  // namespace rbsim
