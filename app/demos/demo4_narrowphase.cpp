// Demo 4: assignment 4, narrow phase (seed 004 "distance tests", "tunnelling"): convex pairs
// approaching, touching and penetrating with distances, normals and manifolds drawn, then a fast
// thin plate against a wall without and with continuous collision detection.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo4Narrowphase() {
  return Demo{4, "narrowphase", "GJK distance, EPA/SAT contacts and manifolds, tunnelling without and with CCD",
              {"narrowphase_pairs.json", "tunnelling_off.json", "tunnelling_on.json", "mesh_contact.json"}};
}

}  // namespace rbsim::app
