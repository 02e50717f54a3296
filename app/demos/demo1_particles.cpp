// Demo 1: assignment 1, particle systems (seed 000's homework "Build a particle system based
// either on F = ma or procedural simulation"; seed 004's cumulative submission): a fountain
// bouncing off the ground and a rigid crate, fire and smoke in a gusty wind, a spring cloth
// falling on a box, and a flock. Each phase is a scene file `rbsim run` plays on its own.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo1Particles() {
  return Demo{1, "particles", "fountain, fire and smoke in wind, a falling cloth, a flock",
              {"particles_fountain.json", "particles_fire_smoke.json", "particles_cloth.json", "particles_flock.json"}};
}

}  // namespace rbsim::app
