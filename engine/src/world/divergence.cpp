// The message of a divergence: which body, which quantities stopped being finite, when, and,
// when it happens at the start of a run, which of the scene's numbers cannot be stepped at all.
#include <cmath>
#include <sstream>
#include <string>

#include "rbsim/integrate/integrator.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/world.h"

namespace rbsim {

namespace {

// The scene keys to blame when a body diverges in the first steps of a run. A step moves the body by
// dt v and changes its velocity by dt F / m and its spin by dt I^-1 tau: whichever of these is
// not a number names the keys it came from.
std::string firstStepCause(const RigidBody& body, const Settings& settings) {
  const double dt = settings.timeStep;
  const std::string key = "bodies." + body.name();
  const double least = body.principalMoments().minCoeff();
  std::ostringstream cause;
  cause << " It diverged at the start of the run: ";
  if (!std::isfinite(dt * body.force().stableNorm() / body.mass())) {
    cause << "the velocity change dt |F| / m = " << dt << " s x " << body.force().stableNorm() << " N / " << body.mass()
          << " kg is not a number; lower the forces on it (" << key << ".forces, " << key
          << ".springs, world.gravity) or raise " << key << ".mass";
  } else if (!std::isfinite(dt * body.torque().stableNorm() / least)) {
    cause << "the spin change dt |tau| / I = " << dt << " s x " << body.torque().stableNorm() << " N m / " << least
          << " kg m^2 is not a number; lower the torques on it (" << key << ".forces and their points) or raise its "
          << "inertia (" << key << ".mass against its size)";
  } else if (!std::isfinite(dt * body.velocity().stableNorm() + body.position().stableNorm())) {
    cause << "its position plus dt |v| = " << body.position().stableNorm() << " m + " << dt << " s x "
          << body.velocity().stableNorm() << " m/s is not a number; lower " << key << ".position or " << key << ".velocity";
  } else {
    cause << "check " << key << ".mass against its size (least principal moment " << least << " kg m^2), its "
          << "velocities and world.dt";
  }
  return cause.str();
}

}  // namespace

void World::reportDivergence(const RigidBody& body, const BodyState& next) const {
  std::string quantities;
  const auto add = [&quantities](bool finite, const char* name) {
    if (!finite) quantities += (quantities.empty() ? "" : ", ") + std::string(name);
  };
  add(next.position.allFinite(), "position");
  add(next.orientation.coeffs().allFinite(), "orientation");
  add(next.linearMomentum.allFinite(), "linear momentum");
  add(next.angularMomentum.allFinite(), "angular momentum");
  std::ostringstream message;
  message << "body '" << body.name() << "': " << quantities << " stopped being finite at step " << stepCount_
          << " (t = " << time() << " s; integrator " << integratorName(settings_.integrator)
          << ", dt = " << settings_.timeStep << " s). Before the step: |v| = " << body.velocity().stableNorm()
          << " m/s, |omega| = " << body.angularVelocity().stableNorm() << " rad/s, |F| = " << body.force().stableNorm()
          << " N, |tau| = " << body.torque().stableNorm() << " N m, m = " << body.mass() << " kg.";
  if (stepCount_ <= 1) message << firstStepCause(body, settings_);
  throw SimulationError(message.str());
}

}  // namespace rbsim
