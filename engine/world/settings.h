#pragma once
// Every tuning value of a World, with its default and unit (as qu3e's q3Settings.h and Jolt's
// PhysicsSettings). Scenes and `--set world.KEY=VALUE` override them.
#include "integrate/integrator.h"
#include "mass/mass_properties.h"
#include "math/types.h"

namespace rbsim {

// A step longer than this is rejected as absurd: at 0.1 s a body falling for one second moves
// ~1 m per step, beyond anything a rigid-body scene at human scale resolves.
inline constexpr double kMaxTimeStep = 0.1;  // [s]

struct Settings {
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);      // [m/s^2], y is up
  double timeStep = 1.0 / 240.0;             // dt [s], in (0, kMaxTimeStep]
  Integrator integrator = Integrator::ExpMap;
  InertiaMethod inertia = InertiaMethod::Exact;  // default for bodies that do not choose
};

}  // namespace rbsim
