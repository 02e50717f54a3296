// Demo 5: assignment 5, contact modelling and collision response (seeds 000, 001, 002): a convex
// box bouncing to rest and one sliding to a stop with friction, boxes colliding, a tumbling mesh
// landing, then a stack of 10 and a pyramid of 55 at rest; last, a column of 20 and a pyramid of
// 210 at dt = 1/60 s with the PGS and the soft-step solver side by side (a "compare" block); and
// balls thrown at the ground under seed 000's friction and the cone, side by side; and seed 001's
// resting contact solved exactly (world.solver lcp) beside PGS and the soft step.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo5Contact() {
  return Demo{5, "contact",
              "impulses with restitution and friction, resting contact, stacks and pyramids, PGS against soft step, "
              "seed 000's friction against the cone, an exact LCP beside both",
              {"contact_response.json", "contact_stacking.json", "contact_solvers.json", "friction_models.json",
               "contact_reference.json"}};
}

}  // namespace rbsim::app
