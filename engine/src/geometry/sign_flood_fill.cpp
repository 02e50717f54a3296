#include "geometry/sign_flood_fill.h"

#include <cstdint>

namespace rbsim {

namespace {

// One occluded edge's evidence: the outward normal of the first triangle crossed tells which side
// its start lies on, that of the last crossed which side its end lies on.
struct Crossing {
  std::size_t from, to;  // grid points, `to` one step along +axis
  bool fromInside, toInside;
};

Vec3 faceNormal(const Mesh& mesh, std::uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  const Vec3& a = mesh.vertices[tri[0]];
  return (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
}

}  // namespace

SignRegions floodFillSigns(const GridLattice& shape, const TriangleBvh& bvh, const Mesh& mesh,
                           const std::vector<SurfaceProximity>& proximity) {
  const std::size_t n = shape.pointCount();
  // Bit `axis` set: the edge from this point to its +axis neighbour is occluded.
  std::vector<std::uint8_t> occluded(n, 0);
  std::vector<Crossing> crossings;
  for (int k = 0; k < shape.dims.z(); ++k) {
    for (int j = 0; j < shape.dims.y(); ++j) {
      for (int i = 0; i < shape.dims.x(); ++i) {
        const Vec3i c(i, j, k);
        const std::size_t p = shape.index(i, j, k);
        for (int axis = 0; axis < 3; ++axis) {
          if (c[axis] + 1 == shape.dims[axis]) continue;
          const std::size_t q = p + shape.stride(axis);
          if (proximity[p] == SurfaceProximity::Far && proximity[q] == SurfaceProximity::Far) continue;
          Vec3i cq = c;
          ++cq[axis];
          const Vec3 a = shape.point(i, j, k), b = shape.point(cq.x(), cq.y(), cq.z());
          const SegmentCrossings hit = bvh.crossings(a, b);
          if (hit.count == 0) continue;
          occluded[p] |= static_cast<std::uint8_t>(1u << axis);
          const Vec3 d = b - a;
          crossings.push_back({p, q, d.dot(faceNormal(mesh, hit.firstTriangle)) > 0.0,
                               d.dot(faceNormal(mesh, hit.lastTriangle)) < 0.0});
        }
      }
    }
  }

  // Flood fill with an explicit stack, seeds in index order: deterministic region numbers.
  constexpr int kUnlabelled = -1;
  std::vector<int> region(n, kUnlabelled);
  std::vector<bool> touchesBoundary, offSurface;
  std::vector<std::size_t> stack;
  int regions = 0;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (region[seed] != kUnlabelled) continue;
    const int label = regions++;
    touchesBoundary.push_back(false);
    offSurface.push_back(false);
    region[seed] = label;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      const Vec3i c = shape.coordinates(p);
      if (proximity[p] != SurfaceProximity::OnSurface) offSurface[label] = true;
      for (int axis = 0; axis < 3; ++axis) {
        const std::size_t step = shape.stride(axis);
        if (c[axis] == 0 || c[axis] + 1 == shape.dims[axis]) touchesBoundary[label] = true;
        if (c[axis] + 1 < shape.dims[axis] && !(occluded[p] >> axis & 1u) &&
            region[p + step] == kUnlabelled) {
          region[p + step] = label;
          stack.push_back(p + step);
        }
        if (c[axis] > 0 && !(occluded[p - step] >> axis & 1u) && region[p - step] == kUnlabelled) {
          region[p - step] = label;
          stack.push_back(p - step);
        }
      }
    }
  }

  // Votes: + for inside, - for outside.
  std::vector<long> vote(regions, 0);
  for (const Crossing& x : crossings) {
    vote[region[x.from]] += x.fromInside ? 1 : -1;
    vote[region[x.to]] += x.toInside ? 1 : -1;
  }
  SignRegions out;
  for (int r = 0; r < regions; ++r) out.regions += offSurface[r] ? 1 : 0;
  out.inside.resize(n);
  out.kind.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const int r = region[p];
    out.inside[p] = !touchesBoundary[r] && vote[r] >= 0;
    out.kind[p] = touchesBoundary[r] ? SdfFillRegion::Outside
                  : !offSurface[r]   ? SdfFillRegion::OnSurface
                  : out.inside[p]    ? SdfFillRegion::Inside
                                     : SdfFillRegion::Cavity;
  }
  return out;
}

}  // namespace rbsim
