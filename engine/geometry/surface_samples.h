#pragma once
// Points on a mesh's surface, for testing one body's surface against another's implicit volume
// (seed 000 "Rigid Body Modeling", "Collision Detection").
#include <vector>

#include "geometry/mesh.h"
#include "math/types.h"

namespace rbsim {

// Every vertex; then, when spacing [m] > 0, the interior points of each edge (each undirected edge
// once) split into ceil(length / spacing) equal parts, and the interior points of each triangle's
// barycentric grid of ceil(longest edge / spacing) steps. Every surface point then lies within
// about `spacing` of a sample (measured bound 1.1 spacing in surface_samples_test.cpp). Spacing
// <= 0: the vertices only. Deterministic: mesh order.
std::vector<Vec3> surfaceSamples(const Mesh& mesh, double spacing);

}  // namespace rbsim
