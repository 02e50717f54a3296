#pragma once
// The bounding volume hierarchy the scene queries go through (world/world_queries.h): a binary
// tree over the bodies' world boxes, built top down by the surface area heuristic over binned
// centroids (Wald 2007, "On fast construction of SAH-based bounding volume hierarchies"; Pharr,
// Jakob and Humphreys, PBRT 3rd ed. section 4.3.2), stored depth first (a node's left child
// follows it) so that a walk reads the array forwards. Static: it is rebuilt, not updated, when
// the World has changed since (the build of 100k boxes costs about what 200 rays do there;
// bench/query_bench).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "rbsim/geometry/aabb.h"
#include "rbsim/math/types.h"
#include "rbsim/shapes/collision_filter.h"
#include "rbsim/shapes/shape.h"

namespace rbsim {

class World;
class RigidBody;

// Bodies per leaf at most, unless they share one centroid (then up to kMaxLeafItems) [bodies]:
// a leaf of a few bodies costs about one more node visit, and two to four halves the nodes.
inline constexpr std::uint32_t kLeafItems = 2;
// A leaf splits by index, whatever the heuristic says, above this many bodies [bodies].
inline constexpr std::uint32_t kMaxLeafItems = 8;
// Deeper than this a walk's fixed stack would overflow [levels]. Below kSahDepth the build splits
// by index, halving, so a tree of up to 2^32 bodies stays within kMaxTreeDepth.
inline constexpr int kMaxTreeDepth = 96;
inline constexpr int kSahDepth = kMaxTreeDepth - 34;

// A body's box as the queries see it: its shape's exact world bounds (a compound's children's).
Aabb queryBounds(const RigidBody& body);

// A copy of what a ray needs of a body of one closed-form shape (sphere, capsule, box, rounded
// box), kept in the tree's leaf order: a ray reads it beside the boxes instead of the body, whose
// lines lie elsewhere (at 1e5 bodies, one ray took 3.5 us reading bodies, 2.6 with these copies;
// bench/query_bench).
struct RayProxy {
  bool closedForm = false;  // false: ask the body (hulls, meshes, compounds)
  Shape shape;              // without hull or faces: a closed-form shape's sizes
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();
  CollisionFilter filter;
};

class QueryTree {
 public:
  explicit QueryTree(std::vector<Aabb> boxes);

  const std::vector<Aabb>& boxes() const { return boxes_; }  // per body index
  const std::vector<std::uint32_t>& items() const { return items_; }  // body indices in leaf order
  std::vector<RayProxy> proxies;  // per entry of items(); filled by queryTree
  std::size_t nodeCount() const { return nodes_.size(); }

  // Calls leaf(item, slot, reach) for each body (index item, items()[slot]) whose box, grown by
  // `grow` on each side, the segment origin + s d, 0 <= s <= reach, meets, nearest box first; leaf
  // may shrink reach (a double&) to the nearest hit so far, and boxes beyond it are skipped.
  template <typename Leaf>
  void walkRay(const Vec3& origin, const Vec3& d, double& reach, const Vec3& grow, Leaf&& leaf) const;
  // Calls visit(item) for each body whose box overlaps `box`.
  template <typename Visit>
  void walkBox(const Aabb& box, Visit&& visit) const;
  // Calls leaf(item, bound) for each body whose box lies within bound of p (bound a double& the
  // leaf may shrink), nearer boxes first.
  template <typename Leaf>
  void walkNearest(const Vec3& p, double& bound, Leaf&& leaf) const;

 private:
  struct Node {
    Aabb box;
    std::uint32_t index = 0;  // leaf: the first of its items; inner node: its right child
    std::uint32_t count = 0;  // leaf: its item count; 0 for an inner node
  };
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth, const std::vector<Vec3>& centres);

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> items_;  // body indices, leaf by leaf
  std::vector<Aabb> boxes_;           // per body index
  std::vector<Aabb> itemBoxes_;       // per entry of items_: the walks read them in this order
};

// The slab test (Kay and Kajiya 1986; Williams et al. 2005): where origin + s d enters `box`
// grown by `grow`, or +infinity when it misses it within [0, reach]. An axis the ray runs along
// (d_k = 0) keeps it when the origin lies within that slab.
inline double slabEntry(const Aabb& box, const Vec3& grow, const Vec3& origin, const Vec3& inverse, double reach) {
  double near = 0.0, far = reach;
  for (int k = 0; k < 3; ++k) {
    const double lo = box.min[k] - grow[k] - origin[k], hi = box.max[k] + grow[k] - origin[k];
    if (std::isinf(inverse[k])) {
      if (lo > 0.0 || hi < 0.0) return std::numeric_limits<double>::infinity();
      continue;
    }
    double t0 = lo * inverse[k], t1 = hi * inverse[k];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (near > far) return std::numeric_limits<double>::infinity();
  }
  return near;
}

// The squared distance from p to a box [m^2], 0 inside.
inline double boxDistanceSquared(const Aabb& box, const Vec3& p) {
  const Vec3 outside = (box.min - p).cwiseMax(p - box.max).cwiseMax(Vec3::Zero());
  return outside.squaredNorm();
}

template <typename Leaf>
void QueryTree::walkRay(const Vec3& origin, const Vec3& d, double& reach, const Vec3& grow, Leaf&& leaf) const {
  if (nodes_.empty()) return;
  const Vec3 inverse = d.cwiseInverse();  // +-infinity on an axis the ray runs along
  struct Entry {
    std::uint32_t node;
    double near;
  };
  Entry stack[kMaxTreeDepth + 2];
  int top = 0;
  const double rootNear = slabEntry(nodes_[0].box, grow, origin, inverse, reach);
  if (rootNear <= reach) stack[top++] = {0, rootNear};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.near > reach) continue;
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      // Each body's own box first: a miss costs no read of the body.
      for (std::uint32_t i = node.index; i < node.index + node.count; ++i) {
        if (slabEntry(itemBoxes_[i], grow, origin, inverse, reach) <= reach) leaf(items_[i], i, reach);
      }
      continue;
    }
    const std::uint32_t left = e.node + 1, right = node.index;
    const double nl = slabEntry(nodes_[left].box, grow, origin, inverse, reach);
    const double nr = slabEntry(nodes_[right].box, grow, origin, inverse, reach);
    // The nearer child goes on top, so it is walked first and its hits prune the other.
    if (nl <= nr) {
      if (nr <= reach) stack[top++] = {right, nr};
      if (nl <= reach) stack[top++] = {left, nl};
    } else {
      if (nl <= reach) stack[top++] = {left, nl};
      if (nr <= reach) stack[top++] = {right, nr};
    }
  }
}

template <typename Visit>
void QueryTree::walkBox(const Aabb& box, Visit&& visit) const {
  if (nodes_.empty()) return;
  std::uint32_t stack[kMaxTreeDepth + 2];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t n = stack[--top];
    const Node& node = nodes_[n];
    if (!node.box.overlaps(box)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.index; i < node.index + node.count; ++i) {
        if (itemBoxes_[i].overlaps(box)) visit(items_[i]);
      }
      continue;
    }
    stack[top++] = node.index;
    stack[top++] = n + 1;
  }
}

template <typename Leaf>
void QueryTree::walkNearest(const Vec3& p, double& bound, Leaf&& leaf) const {
  if (nodes_.empty()) return;
  struct Entry {
    std::uint32_t node;
    double near;  // [m^2]
  };
  Entry stack[kMaxTreeDepth + 2];
  int top = 0;
  // A negative bound (the point inside a solid) still admits boxes that hold the point.
  const auto within = [&](double squared) { return squared <= std::max(bound, 0.0) * std::max(bound, 0.0); };
  const double rootNear = boxDistanceSquared(nodes_[0].box, p);
  if (within(rootNear)) stack[top++] = {0, rootNear};
  while (top > 0) {
    const Entry e = stack[--top];
    if (!within(e.near)) continue;
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      for (std::uint32_t i = node.index; i < node.index + node.count; ++i) {
        if (within(boxDistanceSquared(itemBoxes_[i], p))) leaf(items_[i], bound);
      }
      continue;
    }
    const std::uint32_t left = e.node + 1, right = node.index;
    const double nl = boxDistanceSquared(nodes_[left].box, p), nr = boxDistanceSquared(nodes_[right].box, p);
    if (nl <= nr) {
      if (within(nr)) stack[top++] = {right, nr};
      if (within(nl)) stack[top++] = {left, nl};
    } else {
      if (within(nl)) stack[top++] = {left, nl};
      if (within(nr)) stack[top++] = {right, nr};
    }
  }
}

// What World keeps in its QueryCacheSlot (world/query_cache.h): the tree and the
// geometryVersion (world/queries.h) it was built at.
struct QueryTreeCache {
  std::mutex mutex;
  std::shared_ptr<const QueryTree> tree;  // null until the first query
  std::uint64_t version = 0;
};

// The World's tree for its geometry now: the cached one, or a new one when the World changed
// since it was built. Safe to call from several threads at once.
std::shared_ptr<const QueryTree> queryTree(const World& world);

}  // namespace rbsim
