#include "collision/narrowphase/mesh_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "collision/narrowphase/sdf_contact.h"
#include "collision/narrowphase/triangle_triangle.h"

namespace rbsim {

namespace {

using Corners = std::array<Vec3, 3>;

// Sine of the angle below which two edges count as parallel and give no separating axis, and below
// which an edge axis is taken as lying in both faces [1].
constexpr double kEdgeAxisTolerance = 1e-9;

// B's vertices in A's body frame: p_A = R_A^T (R_B p + x_B - x_A).
std::vector<Vec3> inFrameOf(const PosedMesh& a, const PosedMesh& b) {
  const Mat3 rotation = a.rotation.transpose() * b.rotation;
  const Vec3 translation = a.rotation.transpose() * (b.position - a.position);
  std::vector<Vec3> out;
  out.reserve(b.mesh->vertices.size());
  for (const Vec3& p : b.mesh->vertices) out.push_back(rotation * p + translation);
  return out;
}

Corners cornersOf(const Mesh& mesh, const std::vector<Vec3>& vertices, std::uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  return {vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]};
}

Vec3 normalOf(const Corners& t) { return (t[1] - t[0]).cross(t[2] - t[0]).normalized(); }

// The way two crossing triangles come apart soonest, from A to B: of the separating axis test's
// candidates (the two face normals and the nine cross products of an edge of each; Ericson 5.2.1),
// the one along which B must move least to clear A, max over A of axis.a - min over B of axis.b.
// A face normal is taken outward only (out of A, into B), an edge axis the way that leaves A's face
// and enters B's (or, for parallel faces, from A's centroid to B's).
struct Separation {
  Vec3 normal = Vec3::UnitY();
  double depth = std::numeric_limits<double>::infinity();  // [m]
};
Separation leastSeparation(const Corners& a, const Corners& b, const Vec3& na, const Vec3& nb) {
  Separation best;
  const Vec3 towards = ((b[0] + b[1] + b[2]) - (a[0] + a[1] + a[2])) / 3.0;
  const auto consider = [&](Vec3 axis, bool face) {
    const double length = axis.norm();
    if (!(length > kEdgeAxisTolerance)) return;  // parallel edges: no axis
    axis /= length;
    if (!face) {
      const double facing = axis.dot(na - nb);
      if (facing < 0.0 || (std::abs(facing) <= kEdgeAxisTolerance && axis.dot(towards) < 0.0)) axis = -axis;
    }
    const double aMax = std::max({axis.dot(a[0]), axis.dot(a[1]), axis.dot(a[2])});
    const double bMin = std::min({axis.dot(b[0]), axis.dot(b[1]), axis.dot(b[2])});
    if (aMax - bMin < best.depth) best = {axis, aMax - bMin};
  };
  consider(na, true);
  consider(-nb, true);
  for (int i = 0; i < 3; ++i) {
    const Vec3 ea = (a[(i + 1) % 3] - a[i]).normalized();
    for (int j = 0; j < 3; ++j) consider(ea.cross((b[(j + 1) % 3] - b[j]).normalized()), false);
  }
  return best;
}

template <typename Visit>
void forEachCrossing(const PosedMesh& a, const PosedMesh& b, const std::vector<Vec3>& bVertices, Visit&& visit) {
  const Mat3 rotation = a.rotation.transpose() * b.rotation;
  const Vec3 translation = a.rotation.transpose() * (b.position - a.position);
  a.bvh->overlappingPairs(*b.bvh, rotation, translation, [&](std::uint32_t ta, std::uint32_t tb) {
    const Corners ca = cornersOf(*a.mesh, a.mesh->vertices, ta);
    const Corners cb = cornersOf(*b.mesh, bVertices, tb);
    const TriTriResult r = triangleTriangleIntersection(ca[0], ca[1], ca[2], cb[0], cb[1], cb[2]);
    if (r.intersect) visit(ta, tb, ca, cb, r);
  });
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> crossingTriangles(const PosedMesh& a, const PosedMesh& b) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  const std::vector<Vec3> bVertices = inFrameOf(a, b);
  forEachCrossing(a, b, bVertices, [&](std::uint32_t ta, std::uint32_t tb, const Corners&, const Corners&, const TriTriResult&) {
    pairs.emplace_back(ta, tb);
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<ContactManifold> collideMeshes(const PosedMesh& a, const PosedMesh& b) {
  std::vector<PointContact> points;
  const std::vector<Vec3> bVertices = inFrameOf(a, b);
  forEachCrossing(a, b, bVertices, [&](std::uint32_t, std::uint32_t, const Corners& ca, const Corners& cb, const TriTriResult& r) {
    // Coplanar and degenerate pairs have no segment: the neighbouring triangles that cross
    // them at an angle carry the contact.
    if (!r.hasSegment) return;
    const Vec3 na = normalOf(ca), nb = normalOf(cb);
    if (!na.allFinite() || !nb.allFinite()) return;
    const Separation apart = leastSeparation(ca, cb, na, nb);
    const Vec3 middle = 0.5 * (r.segment[0] + r.segment[1]);
    points.push_back({a.rotation * middle + a.position, a.rotation * apart.normal, apart.depth});
  });
  return manifoldsByNormal(points);
}

}  // namespace rbsim
