#pragma once
// Bounding-volume hierarchy of axis-aligned boxes over a mesh's triangles (seed 000 "Constructing
// Signed Distance Functions": "an acceleration structure is useful, e.g. bounding box hierarchy").
// It answers the signed distance grid's three questions: the closest surface point within a
// radius (the seed's sphere around a grid point), the nearest triangle anywhere, and which
// triangles a segment between two grid points crosses (the sign flood fill's occlusion).
// Closest points on a triangle are Ericson's Voronoi-region method, closestPointOnTriangle in
// geometry/distance.h (exact up to rounding in all seven regions).
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "rbsim/geometry/aabb.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/math/types.h"

namespace rbsim {

// Triangles per leaf at most: below this, testing them all is cheaper than descending further.
inline constexpr std::uint32_t kBvhLeafTriangles = 4;
// Tolerance of the segment-triangle test [1], on barycentric coordinates and on the segment
// parameter: a segment through a shared edge or vertex must count as crossing at least one of
// the triangles there, or the sign flood fill would leak through the crack.
inline constexpr double kSegmentTriangleTolerance = 1e-9;

struct SurfacePoint {
  Vec3 point = Vec3::Zero();   // on the mesh [m]
  double distance = 0.0;       // from the query point [m]
  std::uint32_t triangle = 0;  // index into Mesh::triangles
};

// The crossings of a segment a -> b with the mesh: the first and the last along the segment.
struct SegmentCrossings {
  int count = 0;                    // triangles crossed (a segment through an edge counts both)
  std::uint32_t firstTriangle = 0;  // smallest segment parameter t
  std::uint32_t lastTriangle = 0;   // largest t
};

// Whether the closed segment pq meets the closed triangle abc (Moller-Trumbore with the tolerance
// above); t receives the segment parameter of the meeting point. A segment in the triangle's plane
// does not cross it and returns false.
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                            const Vec3& c, double& t);

// Margin of the self-crossing test [1], relative to the triangles' sizes: an edge must pass
// through the other triangle's plane and interior by more than this, so surfaces that only touch
// (a vertex on a face, to rounding) are not taken for crossing.
inline constexpr double kSelfCrossingTolerance = 1e-9;

// Two triangles of a mesh that share no edge and pierce each other.
struct SelfCrossing {
  bool found = false;
  bool exhausted = false;      // the pair budget ran out first: nothing is known
  std::uint32_t first = 0;     // index into Mesh::triangles
  std::uint32_t second = 0;
  Vec3 point = Vec3::Zero();   // where an edge of one passes through the other [m]
  double pairTests = 0.0;      // triangle pairs tested [1]
};

// Whether an edge of either triangle passes through the other's interior (beyond the margin).
// Triangles sharing an edge never cross; sharing one corner they can (a fold through it).
bool trianglesCross(const Vec3 (&t)[3], const Vec3 (&u)[3], Vec3& point);

class TriangleBvh {
 public:
  // Copies the mesh's vertices and triangles. Indices must be valid (checkMesh); the mesh needs
  // at least one triangle.
  explicit TriangleBvh(const Mesh& mesh);

  // The closest surface point no farther than `radius` [m] from p, or none.
  std::optional<SurfacePoint> closestWithin(const Vec3& p, double radius) const;
  // The closest surface point of the whole mesh.
  SurfacePoint nearest(const Vec3& p) const;
  SegmentCrossings crossings(const Vec3& a, const Vec3& b) const;
  // The first pair of triangles (by a deterministic traversal) that cross each other and share no
  // edge, testing only pairs whose boxes overlap and at most `maxPairTests` of them.
  SelfCrossing selfCrossing(double maxPairTests) const;

  // Every pair (triangle of this mesh, triangle of `other`) whose leaves' boxes overlap, `other`
  // placed in this mesh's frame by p -> rotation p + translation (its boxes are bounded there by
  // the boxes of their rotated corners). Simultaneous descent, splitting the larger node.
  void overlappingPairs(const TriangleBvh& other, const Mat3& rotation, const Vec3& translation,
                        const std::function<void(std::uint32_t, std::uint32_t)>& pair) const;

  // The triangles whose boxes overlap `box` (this mesh's frame), appended to `out`: a descent
  // with a fixed stack, allocating nothing once `out` has room (the narrow phase's hot path).
  void overlapping(const Aabb& box, std::vector<std::uint32_t>& out) const;
  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  // Per triangle, which of its edges are felt (geometry/triangle_edges.h activeEdges).
  std::uint8_t activeEdges(std::uint32_t triangle) const { return activeEdges_[triangle]; }

  std::size_t triangleCount() const { return triangles_.size(); }
  std::size_t nodeCount() const { return nodes_.size(); }
  const Aabb& bounds() const { return nodes_.front().box; }

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: first entry of order_; inner: index of the left child
    std::uint32_t count = 0;  // leaf: number of triangles; inner: 0 (the right child is first + 1)
  };
  void buildNode(std::uint32_t index, std::uint32_t begin, std::uint32_t end,
                 const std::vector<Vec3>& centroids);
  // Closest point with distance^2 below best2, updating best and best2.
  void closest(const Vec3& p, double& best2, SurfacePoint& best) const;
  // Tests every pair of leaf a's and leaf b's triangles (a == b: each pair once).
  void crossLeaves(const Node& a, const Node& b, bool same, double maxPairTests, SelfCrossing& out) const;

  std::vector<Vec3> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<std::uint32_t> order_;  // triangle indices, grouped by leaf
  std::vector<Node> nodes_;           // nodes_[0] is the root
  std::vector<std::uint8_t> activeEdges_;  // per triangle, bit k: edge k is active
};

}  // namespace rbsim
