#pragma once
// Ways to cut a convex body into pieces before it breaks (seed 000 "Fracture"): by planes, or
// into the Voronoi cells of random sites, which gives the irregular shards of shattered glass or
// stone. Every piece is closed and convex, and together they fill the body exactly.
#include <cstdint>
#include <limits>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

struct CutPlane {
  Vec3 normal = Vec3::UnitY();  // unit
  double offset = 0.0;          // the plane normal . p = offset [m], body frame
};

// Every piece the planes cut the convex mesh into (each plane splits every piece it crosses).
// Throws std::invalid_argument for a plane whose normal is not unit or finite, and
// std::length_error, naming the plane and the count, as soon as the pieces would exceed
// `maxPieces` (n planes can make ~n^3 / 6 pieces).
std::vector<Mesh> cutByPlanes(const Mesh& convex, const std::vector<CutPlane>& planes,
                              std::size_t maxPieces = std::numeric_limits<std::size_t>::max());

// The Voronoi cell of each site clipped to the convex mesh: the points nearer that site than any
// other, cut out by the bisecting planes of the site pairs. Sites whose cell misses the mesh give
// no piece.
std::vector<Mesh> voronoiPieces(const Mesh& convex, const std::vector<Vec3>& sites);

// `count` sites uniform inside the convex mesh (rejection sampling in its bounding box against
// its face planes), reproducible from the seed. Throws std::invalid_argument for count < 2.
std::vector<Vec3> sitesInside(const Mesh& convex, int count, std::uint64_t seed);

}  // namespace rbsim
