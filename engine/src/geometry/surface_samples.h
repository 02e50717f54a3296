#pragma once
// Points on a mesh's surface, for testing one body's surface against another's implicit volume
// (seed 000 "Rigid Body Modeling", "Collision Detection").
#include <string>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Every vertex; then, when spacing [m] > 0, the interior points of each edge (each undirected edge
// once) split into ceil(length / spacing) equal parts, and the interior points of each triangle's
// barycentric grid of ceil(longest edge / spacing) steps. Every surface point then lies within
// about `spacing` of a sample (measured bound 1.1 spacing in surface_samples_test.cpp). Spacing
// <= 0: the vertices only. Deterministic: mesh order.
// Throws std::invalid_argument (with surfaceSampleBudgetProblem's words) when the samples would
// exceed kMaxSurfaceSamples, before any is made.
std::vector<Vec3> surfaceSamples(const Mesh& mesh, double spacing);

// Budget of one body's samples: each is 24 bytes and is tested against the other bodies' grids
// in every step, so 4e6 samples are ~100 MB and ~0.1 s per step and contact pair.
inline constexpr double kMaxSurfaceSamples = 4e6;  // [samples]
// How many samples surfaceSamples makes at most (each edge counted once per triangle), computed
// in double without making any; then "spacing 0.0001 m on mesh 'm' (area 6 m^2) needs up to
// 7.2e+08 samples; the limit is 4e+06", or empty when within the budget.
double surfaceSampleEstimate(const Mesh& mesh, double spacing);
std::string surfaceSampleBudgetProblem(const Mesh& mesh, double spacing);

}  // namespace rbsim
