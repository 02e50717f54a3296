// Demo 3: assignment 3, broad phase (seed 004 "sweep and prune"): hundreds of bodies, their
// AABBs, the overlapping pairs, and sweep and prune checked against brute force every frame.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo3Broadphase() {
  return Demo{3, "broadphase", "sweep and prune over 300 moving boxes against brute force",
              {"broadphase_crowd.json"}};
}

}  // namespace rbsim::app
