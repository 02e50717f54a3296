#pragma once
// Thrown by World::step when a body's state leaves the finite numbers (an integrator driven past
// its stability limit): the run stops with the body, the step and the cause, never with NaN.
#include <stdexcept>
#include <string>

namespace rbsim {

class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rbsim
