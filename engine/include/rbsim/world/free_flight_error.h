#pragma once
// The live error of the chosen integrator against the exact torque-free motion (issue 21), for one
// body: while no torque acts on it, the exact flow (integrate/free_rigid_body.h) from its state at
// the last moment something did (a contact, a torque, a spring, sleep) says where it should be.
// The angle between that orientation and the simulated one, and the relative error of the spin
// energy, are what the integrator added since: a student sees expmap lose the Dzhanibekov flip
// while exact holds it. Only the body's spin is compared; gravity exerts no torque.
#include <cstddef>
#include <optional>

#include "rbsim/integrate/free_rigid_body.h"
#include "rbsim/world/world.h"

namespace rbsim {

class FreeFlightError {
 public:
  explicit FreeFlightError(BodyId body) : body_(body) {}
  BodyId body() const { return body_; }

  // After every step of the world, and once before the first: restarts the exact motion from the
  // body's state when anything but the integrator turned it during the step.
  void observe(const World& world);

  struct Reading {
    bool tracked = false;  // a dynamic, awake body with no torque since `since`
    double since = 0.0;    // time of the epoch [s]
    double angle = 0.0;    // angle between the simulated and the exact orientation [rad]
    double energy = 0.0;   // E_spin / E_spin,exact - 1 [1]; E_spin = L . omega / 2
  };
  Reading read(const World& world) const;

 private:
  BodyId body_;
  std::optional<FreeRigidBodyFlow> flow_;
  double epochTime_ = 0.0;  // [s]
  double spinEnergy_ = 0.0;  // at the epoch, which the exact motion keeps [J]
  Quat bodyToPrincipal_ = Quat::Identity();
};

}  // namespace rbsim
