#include "fracture/pieces.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "fracture/convex_clip.h"
#include "rbsim/math/uniform_random.h"

namespace rbsim {

namespace {

// Rejection sampling needs the body to fill some of its box; a sliver filling less than 1e-6 of
// it would take millions of draws per site, so the search gives up there with an error.
constexpr int kMaxDrawsPerSite = 1000000;  // [draws]

struct HullPlane {
  Vec3 normal;
  double offset;
};

std::vector<HullPlane> facePlanes(const Mesh& mesh) {
  std::vector<HullPlane> planes;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    const double length = n.norm();
    if (length == 0.0) continue;
    planes.push_back({n / length, n.dot(a) / length});
  }
  return planes;
}

bool hasVolume(const Mesh& piece) { return !piece.triangles.empty(); }

// The most pieces n planes can cut a convex body into: 1 + n + C(n, 2) + C(n, 3) (planes in
// general position; the cake numbers).
unsigned long long maxPiecesOf(std::size_t planes) {
  const unsigned long long n = planes;
  return 1 + n + n * (n - 1) / 2 + n * (n - 1) * (n - 2) / 6;
}

}  // namespace

std::vector<Mesh> cutByPlanes(const Mesh& convex, const std::vector<CutPlane>& planes, std::size_t maxPieces) {
  const double tolerance = clipTolerance(convex);
  std::vector<Mesh> pieces{convex};
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const CutPlane& plane = planes[k];
    if (!plane.normal.allFinite() || std::abs(plane.normal.norm() - 1.0) > 1e-9 || !std::isfinite(plane.offset)) {
      throw std::invalid_argument("cut plane " + std::to_string(k) + ": the normal must be a finite unit vector");
    }
    std::vector<Mesh> next;
    for (const Mesh& piece : pieces) {
      Mesh below = clipConvexMesh(piece, plane.normal, plane.offset, tolerance);
      Mesh above = clipConvexMesh(piece, -plane.normal, -plane.offset, tolerance);
      if (hasVolume(below)) next.push_back(std::move(below));
      if (hasVolume(above)) next.push_back(std::move(above));
      if (next.size() > maxPieces) {
        throw std::length_error("plane " + std::to_string(k) + " brings the body to at least " + std::to_string(next.size()) +
                                " pieces ("  + std::to_string(planes.size()) +
                                " planes can make up to " + std::to_string(maxPiecesOf(planes.size())) +
                                "); the limit is " + std::to_string(maxPieces) + " pieces");
      }
    }
    pieces = std::move(next);
  }
  return pieces;
}

std::vector<Mesh> voronoiPieces(const Mesh& convex, const std::vector<Vec3>& sites) {
  const double tolerance = clipTolerance(convex);
  std::vector<Mesh> pieces;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    Mesh cell = convex;
    for (std::size_t j = 0; j < sites.size() && hasVolume(cell); ++j) {
      if (j == i) continue;
      const Vec3 gap = sites[j] - sites[i];
      const double length = gap.norm();
      if (length == 0.0) continue;  // a repeated site shares its cell with the first copy
      const Vec3 normal = gap / length;
      cell = clipConvexMesh(cell, normal, normal.dot(0.5 * (sites[i] + sites[j])), tolerance);
    }
    if (hasVolume(cell)) pieces.push_back(std::move(cell));
  }
  return pieces;
}

std::vector<Vec3> sitesInside(const Mesh& convex, int count, std::uint64_t seed) {
  if (count < 2) throw std::invalid_argument("fracture needs at least 2 pieces");
  const std::vector<HullPlane> planes = facePlanes(convex);
  const Vec3 lo = convex.boundsMin(), hi = convex.boundsMax();
  UniformRandom random(seed);
  std::vector<Vec3> sites;
  for (int draws = 0; static_cast<int>(sites.size()) < count;) {
    // z, y, x: one draw a statement, in the order GCC evaluated the three arguments this was
    // (C++ leaves it unspecified; clang goes left to right): the same sites with every compiler.
    const double z = random.between(lo.z(), hi.z());
    const double y = random.between(lo.y(), hi.y());
    const double x = random.between(lo.x(), hi.x());
    const Vec3 p(x, y, z);
    bool inside = true;
    for (const HullPlane& plane : planes) inside = inside && plane.normal.dot(p) < plane.offset;
    if (inside) {
      sites.push_back(p);
      draws = 0;
    } else if (++draws > kMaxDrawsPerSite) {
      throw std::invalid_argument("no room for fracture sites inside mesh '" + convex.name + "'");
    }
  }
  return sites;
}

}  // namespace rbsim
