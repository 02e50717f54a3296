#pragma once
// Surface material of a body or a plane: the coefficient of restitution and the static and
// kinetic friction coefficients of seed 000 "Collision Response" and "Friction".
#include <algorithm>
#include <cmath>
#include <string>

namespace rbsim {

struct Material {
  double restitution = 0.0;      // c_R [1] in [0, 1]: 0 stops the approach, 1 reverses it
  double staticFriction = 0.6;   // mu_s [1] >= 0: sticking while |j_T| <= mu_s j_N
  double kineticFriction = 0.5;  // mu_k [1] in [0, mu_s]: sliding impulse mu_k j_N
};

// The material of a touching pair. Restitution takes the livelier surface (a rubber ball bounces
// on concrete); friction the geometric mean, so a frictionless surface makes the pair
// frictionless (as Box2D's b2MixFriction and b2MixRestitution).
inline Material combine(const Material& a, const Material& b) {
  return {std::max(a.restitution, b.restitution), std::sqrt(a.staticFriction * b.staticFriction),
          std::sqrt(a.kineticFriction * b.kineticFriction)};
}

// Empty when usable; otherwise what is wrong, naming the field.
inline std::string checkMaterial(const Material& m) {
  if (!(m.restitution >= 0.0 && m.restitution <= 1.0)) return "restitution: expected a value in [0, 1]";
  if (!(m.staticFriction >= 0.0) || !std::isfinite(m.staticFriction)) return "friction_static: expected a finite value >= 0";
  if (!(m.kineticFriction >= 0.0) || !std::isfinite(m.kineticFriction)) return "friction_kinetic: expected a finite value >= 0";
  if (m.kineticFriction > m.staticFriction) return "friction_kinetic: expected a value <= friction_static (mu_k <= mu_s)";
  return {};
}

}  // namespace rbsim
