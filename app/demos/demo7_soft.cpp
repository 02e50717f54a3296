// Demo 7: deformable bodies by tetrahedral FEM (seed 002 section 1): a jelly cube dropping and
// wobbling on the ground while a rigid box lands on it, then a soft bar clamped at one end
// bending under gravity beside a stiffer neo-Hookean one.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo7Soft() {
  return Demo{7, "soft", "FEM soft bodies: a jelly cube hit by a rigid box, soft bars bending under gravity, 2D boxes tumbling",
              {"soft_jelly.json", "soft_bars.json", "planar_tumbling.json"}};
}

}  // namespace rbsim::app
