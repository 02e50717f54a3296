// Demo 5: assignment 5, contact modelling and collision response (seeds 000, 001, 002): a convex
// box bouncing to rest and one sliding to a stop with friction, boxes colliding, a tumbling mesh
// landing, then a stack of 10 and a pyramid of 55 at rest.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo5Contact() {
  return Demo{5, "contact", "impulses with restitution and friction, resting contact, a stack and a pyramid",
              {"contact_response.json", "contact_stacking.json"}};
}

}  // namespace rbsim::app
