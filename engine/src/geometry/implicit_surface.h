#pragma once
// Analytic implicit surfaces (seed 000 "Analytic Implicit Surfaces"): phi(x) < 0 inside, > 0
// outside, 0 on the surface, in body space, centred on the body origin. The sphere and the box are
// exact signed distances (|grad phi| = 1 wherever the gradient exists); the ellipsoid's seed
// function is not a distance, so EllipsoidSurface uses a documented first-order approximation.
#include "rbsim/math/types.h"

namespace rbsim {

// Sphere of the given radius [m]: phi = |p| - radius, exact.
struct SphereSurface {
  double radius = 1.0;  // [m]

  double phi(const Vec3& p) const;
  // p / |p|; at the centre, where every direction is nearest, +x.
  Vec3 gradient(const Vec3& p) const;
};

// Axis-aligned box of the given half extents [m]: the exact signed distance. Outside,
// |max(q, 0)| with q = |p| - h per axis; inside, the largest q (distance to the nearest face).
struct BoxSurface {
  Vec3 halfExtents = Vec3::Constant(0.5);  // [m]

  double phi(const Vec3& p) const;
  // Outside: towards the nearest surface point. Inside: the outward normal of the nearest face
  // (on the medial planes, where faces tie, the first axis among them).
  Vec3 gradient(const Vec3& p) const;
};

// Ellipsoid with semi-axes `radii` [m]. The seed's f = (x/rx)^2 + (y/ry)^2 + (z/rz)^2 - 1 has the
// right zero set and sign but is no distance (f ~ |p|^2 far away). We use the first-order distance
// of the degree-one function g = |D p| - 1 (D = diag(1/r)): phi = g / |grad g| = k0 (k0 - 1) / k1
// with k0 = |D p|, k1 = |D^2 p|. It is exact on the surface (phi = 0), at distance along the three
// axes, and for a sphere; elsewhere its relative error grows with the aspect ratio: for radii
// (1, 0.5, 0.25) m measured at most 36 % of the true distance 0.05 m to 0.5 m outside and 29 %
// 0.02 m to 0.1 m deep (tests/engine/geometry/implicit_surface_test.cpp). Its sign is exact.
struct EllipsoidSurface {
  Vec3 radii = Vec3::Ones();  // [m]

  double phi(const Vec3& p) const;
  // The analytic gradient of phi above (not normalised: |grad phi| = 1 only where phi is exact).
  // At the centre, +x.
  Vec3 gradient(const Vec3& p) const;
};

}  // namespace rbsim
