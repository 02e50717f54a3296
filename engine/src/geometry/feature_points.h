#pragma once
// Points on an implicit surface that keep its sharp edges and corners: one per grid cell the
// surface crosses, placed as dual contouring places its vertices (Ju, Losasso, Schaefer and
// Warren 2002, "Dual Contouring of Hermite Data"). In each cell the exact crossings p_i of its
// edges and the exact normals n_i there give the quadratic error sum_i (n_i . (x - p_i))^2; its
// minimiser nearest the crossings' mean is the corner where three faces meet in the cell, the
// point of the edge where two do, and a point of the face where one does, at any resolution.
// A marching mesh (geometry/marching_tetrahedra.h) only has vertices on grid edges, so it bevels
// every edge and corner the grid does not hit.
#include <functional>
#include <vector>

#include "rbsim/geometry/signed_distance_grid.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Eigenvalues of sum_i n_i n_i^T below this fraction of the largest are taken as zero (Ju et al.'s
// truncated pseudo-inverse): normals that differ by less than ~18 degrees do not make an edge, and
// the point stays on the face near the crossings' mean rather than far off along a flat fold.
inline constexpr double kFeatureEigenRatio = 0.1;  // [1]
// A crossing is refined until its bracket is this fraction of a cell.
inline constexpr double kCrossingTolerance = 1e-10;  // [1]
// Newton steps projecting a point onto phi = 0 at most (exact points need none).
inline constexpr int kProjectionSteps = 4;

// The exact field: phi [m] (< 0 inside) and its gradient, both at a point of the grid's frame.
struct ExactField {
  std::function<double(const Vec3&)> phi;
  std::function<Vec3(const Vec3&)> gradient;
};

// One point per cell of `grid` whose corner values change sign (a value < 0 is inside), on the
// exact surface to rounding; deterministic (cell order, x fastest).
std::vector<Vec3> featurePoints(const SignedDistanceGrid& grid, const ExactField& field);

// The point reached from p by at most kProjectionSteps Newton steps x -= phi grad / |grad|^2.
Vec3 projectOntoSurface(const Vec3& p, const ExactField& field, double tolerance);

}  // namespace rbsim
