#pragma once
// The box pile of issue 5's benchmark, shared by contact_pile (rbsim) and bullet_pile (Bullet), so
// both engines drop exactly the same boxes: N unit boxes of 1 kg in 10 layers of a loose grid.
#include <cmath>

namespace rbsim::bench {

inline constexpr double kPileTimeStep = 1.0 / 60.0;  // [s]
inline constexpr int kPileSolverIterations = 10;     // [sweeps]
inline constexpr int kPileSteps = 600;
inline constexpr int kPileTimedSteps = 300;          // the last ones: the pile has landed and settles
inline constexpr double kPileGridSpacing = 1.5;      // [m] between box centres, so none start in contact
inline constexpr double kPileBoxSize = 1.0;          // [m] edge
inline constexpr double kPileBoxMass = 1.0;          // [kg]
inline constexpr double kPileRestSpeed = 0.05;       // [m/s]: "at rest" when every box is slower
inline constexpr double kPileFriction = 0.5;         // [1] kinetic; Bullet has one coefficient
inline constexpr int kPileLayers = 10;

struct PileCentre {
  double x, y, z;  // [m]
};

// Centre of box i of a pile of count boxes; odd layers are shifted by half a box, so that boxes
// land on edges and tumble.
inline PileCentre pileBoxCentre(int i, int count) {
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count) / kPileLayers)));
  const int layer = i / (side * side), cell = i % (side * side);
  const double shift = (layer % 2) * 0.5 * kPileBoxSize;
  return {(cell % side) * kPileGridSpacing + shift, kPileBoxSize + layer * kPileGridSpacing,
          (cell / side) * kPileGridSpacing + shift};
}

}  // namespace rbsim::bench
