#pragma once
// The sign of phi (seed 000 "Sign of phi"): a flood fill over the grid points in which the edge
// between two neighbouring points is occluded when the segment between them crosses the mesh.
#include <cstddef>
#include <vector>

#include "rbsim/geometry/grid_lattice.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "geometry/triangle_bvh.h"

namespace rbsim {

#include <cstdint>

// A grid point lying on the surface is cut off from every neighbour (each of its edges touches the
// surface), so it forms a region of its own; such regions are not counted.
inline constexpr double kOnSurfaceCells = 1e-9;  // [cells] distance that counts as on the surface

enum class SurfaceProximity : std::uint8_t { Far, WithinOneCell, OnSurface };

struct SignRegions {
  std::vector<bool> inside;  // per grid point
  std::vector<SdfFillRegion> kind;  // per grid point: the kind of its region (never Unknown)
  int regions = 0;           // connected regions with a point off the surface
};

// `proximity[p]` must be WithinOneCell (or OnSurface) for every point within one cell of the
// surface: only edges with such an end can cross it (an edge is one cell long), so only they are
// tested against the mesh.
// Regions touching the grid boundary are outside, as in the seed. Every other region takes the
// side that the mesh's outward normals give it where its occluded edges cross the surface (a
// majority vote over the crossings): the seed's "the other region is inside" for a solid, and also
// right when a region is a cavity (a hollow ball's inner shell faces inward, so the cavity is
// outside). A region with as many votes each way (only possible for a few points lying exactly on
// the surface, whose every edge touches it) is inside.
SignRegions floodFillSigns(const GridLattice& shape, const TriangleBvh& bvh, const Mesh& mesh,
                           const std::vector<SurfaceProximity>& proximity);

}  // namespace rbsim
