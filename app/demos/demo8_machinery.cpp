// Demo 8: scenes of many shapes and moving machinery (issue 40): a table of five boxes, a hammer
// and a dumbbell as compound bodies, a turntable and a lift on prescribed motions, two balls of
// one collision group passing through each other; then a washer drum of 40 hulls turning about
// its axis, tumbling boxes (Box3D's washer benchmark, smaller); last, ragdolls raining onto a
// triangle-mesh ground.
#include "demos/demo.h"

namespace rbsim::app {

Demo demo8Machinery() {
  return Demo{8, "machinery",
              "compound bodies (a table of five boxes, a hammer, a dumbbell), collision filters, kinematic bodies "
              "turning about a pivot and following keyframes, a washer drum tumbling boxes, ragdolls raining on a mesh ground",
              {"machinery_table.json", "machinery_washer.json", "machinery_rain.json"}};
}

}  // namespace rbsim::app
