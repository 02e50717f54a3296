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

// Thrown by World::step when a step would hold more than the engine bounds it to (the broad
// phase's pairs: rbsim/collision/broadphase/broad_phase.h kMaxBroadPhasePairs), before it
// allocates them: bodies piled into one place overlap in n^2 / 2 pairs, and 1e5 boxes at one
// point ended in std::bad_alloc. Not a divergence: the input asks for more than a step can hold.
class StepLimitError : public SimulationError {
 public:
  using SimulationError::SimulationError;
};

}  // namespace rbsim
