// Demo 6: implicit surfaces, non-convex collisions and fracture (seed 000 "Rigid Body Modeling",
// "Discrete Implicit Surfaces", "Collision Detection", "Fracture"): non-convex bodies tumbling
// into a bowl, particles pouring over meshes, a wall that shatters and a column that splits, and a
// mug made by CSG of analytic implicit surfaces ("Efficient boolean operations") catching sand and boxes.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo6Implicit() {
  return Demo{6, "implicit", "signed distance grids: non-convex bodies in a bowl, particles over meshes, fracture, a CSG mug",
              {"sdf_bowl.json", "sdf_pour.json", "fracture_wall.json", "csg_cup.json"}};
}

}  // namespace rbsim::app
