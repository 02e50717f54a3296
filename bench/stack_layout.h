#pragma once
// The stacking scenes of issue 18, shared by contact_scenes (rbsim) and bullet_scenes (Bullet) so
// both engines build exactly the same boxes: a column of unit boxes, and a pyramid wall (rows of
// unit boxes, each row one shorter and centred on the row below, as Box3D's large_pyramid), every box
// touching its neighbours at the start, as a user building a stack by hand would leave it.
#include <string>
#include <vector>

namespace rbsim::bench {

inline constexpr double kStackTimeStep = 1.0 / 60.0;  // [s]
inline constexpr double kStackBoxSize = 1.0;          // [m] edge
inline constexpr double kStackBoxMass = 1.0;          // [kg]
inline constexpr double kStackFriction = 0.6;         // [1]
inline constexpr double kStackSeconds = 10.0;         // [s] simulated

struct BoxCentre {
  double x, y, z;  // [m]
};

inline std::vector<BoxCentre> columnLayout(int boxes) {
  std::vector<BoxCentre> out;
  for (int i = 0; i < boxes; ++i) out.push_back({0.0, (0.5 + i) * kStackBoxSize, 0.0});
  return out;
}

// rows(rows + 1) / 2 boxes: row r (from 0 at the bottom) holds rows - r boxes, offset by half a box.
inline std::vector<BoxCentre> pyramidLayout(int rows) {
  std::vector<BoxCentre> out;
  for (int r = 0; r < rows; ++r) {
    const int count = rows - r;
    for (int i = 0; i < count; ++i) {
      out.push_back({(i - 0.5 * (count - 1)) * kStackBoxSize, (0.5 + r) * kStackBoxSize, 0.0});
    }
  }
  return out;
}

}  // namespace rbsim::bench
