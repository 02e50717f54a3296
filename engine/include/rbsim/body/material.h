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

// The checks of a material's keys (a scene's "restitution", "friction_static", "friction_kinetic"),
// one each, shared by the scene loader and setBodyMaterial: empty when usable, otherwise
// what was expected.
inline std::string restitutionProblem(double restitution) {
  return restitution >= 0.0 && restitution <= 1.0 ? std::string() : "expected a coefficient in [0, 1]";
}
// `symbol` names the coefficient in the message: "(mu_s)" or "(mu_k)".
inline std::string frictionProblem(double friction, const char* symbol) {
  return friction >= 0.0 && std::isfinite(friction) ? std::string() : std::string("expected a finite value >= 0 ") + symbol;
}
// Reported against friction_kinetic.
inline std::string frictionOrderProblem(const Material& m) {
  return m.kineticFriction <= m.staticFriction ? std::string() : "expected mu_k <= friction_static (mu_s)";
}

// Empty when usable; otherwise what is wrong, naming the field ("restitution: expected ...").
inline std::string checkMaterial(const Material& m) {
  if (std::string p = restitutionProblem(m.restitution); !p.empty()) return "restitution: " + p;
  if (std::string p = frictionProblem(m.staticFriction, "(mu_s)"); !p.empty()) return "friction_static: " + p;
  if (std::string p = frictionProblem(m.kineticFriction, "(mu_k)"); !p.empty()) return "friction_kinetic: " + p;
  if (std::string p = frictionOrderProblem(m); !p.empty()) return "friction_kinetic: " + p;
  return {};
}

}  // namespace rbsim
