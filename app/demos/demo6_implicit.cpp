// Demo 6: implicit surfaces, non-convex collisions and fracture (seed 000 "Rigid Body Modeling",
// "Constructing Signed Distance Functions", "Discrete Implicit Surfaces", "Collision Detection",
// "Fracture"): how a body's signed distance grid is built (a slice of phi with its zero contour,
// the narrow band, fast marching and the flood fill's regions), non-convex bodies tumbling into a
// bowl, particles pouring over meshes, a wall that shatters and a column that splits, and a mug
// made by CSG of analytic implicit surfaces ("Efficient boolean operations") catching sand and boxes.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo6Implicit() {
  return Demo{6, "implicit",
              "signed distance grids: a slice of phi with its narrow band and flood fill, non-convex bodies in a bowl, particles over meshes, fracture, a CSG mug",
              {"sdf_slice.json", "sdf_bowl.json", "sdf_pour.json", "fracture_wall.json", "csg_cup.json"}};
}

}  // namespace rbsim::app
