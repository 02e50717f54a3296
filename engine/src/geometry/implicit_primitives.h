#pragma once
// More analytic implicit surfaces (seed 000 "Analytic Implicit Surfaces"), each the exact signed
// distance (phi < 0 inside, |grad phi| = 1), in its own frame, centred on the origin with its axis
// along y; the closed forms are Hart's (1996, "Sphere tracing", The Visual Computer 12(10)).
#include "rbsim/math/types.h"

namespace rbsim {

// Torus in the xz plane: ring radius majorRadius R [m], tube radius minorRadius r [m] (r < R).
// phi = |(sqrt(x^2 + z^2) - R, y)| - r.
struct TorusSurface {
  double majorRadius = 0.5;  // [m]
  double minorRadius = 0.15; // [m]
  double phi(const Vec3& p) const;
};

// Capsule: the points within `radius` [m] of the segment from (0, -halfLength, 0) to
// (0, halfLength, 0) [m]. phi = |p - (0, clamp(y, -h, h), 0)| - r.
struct CapsuleSurface {
  double radius = 0.25;     // [m]
  double halfLength = 0.5;  // [m]
  double phi(const Vec3& p) const;
};

// Solid cylinder of `radius` [m] from y = -halfHeight to y = halfHeight [m], with flat ends.
// With d = (sqrt(x^2 + z^2) - r, |y| - h): phi = min(max(d_x, d_y), 0) + |max(d, 0)|.
struct CylinderSurface {
  double radius = 0.5;      // [m]
  double halfHeight = 0.5;  // [m]
  double phi(const Vec3& p) const;
};

}  // namespace rbsim
