#include "world/query_tree.h"

#include <array>

#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"
#include "world/compound_contacts.h"
#include "world/world_access.h"

namespace rbsim {

namespace {

// Centroid bins per split (Wald 2007 finds 16 as good as a full sweep) [bins].
constexpr int kSahBins = 16;
// An inner node costs this many box tests' time against one body test (PBRT's 1/8) [1].
constexpr double kSahTraversalCost = 0.125;

double halfSurfaceArea(const Aabb& b) {
  if (b.empty()) return 0.0;
  const Vec3 e = b.extents();
  return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
}

}  // namespace

Aabb queryBounds(const RigidBody& body) {
  if (body.isCompound()) return compoundBounds(body);
  // A mesh body answers by the triangles of its drawn mesh (world_queries.h), so its vertices bound it.
  if (body.shape().type == ShapeType::Mesh) return Aabb::of(body.worldVertices());
  const auto [lo, hi] = body.shape().worldBounds(body.rotation(), body.position());
  return {lo, hi};
}

QueryTree::QueryTree(std::vector<Aabb> boxes) : boxes_(std::move(boxes)) {
  const auto n = static_cast<std::uint32_t>(boxes_.size());
  if (n == 0) return;
  items_.resize(n);
  std::vector<Vec3> centres(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    items_[i] = i;
    centres[i] = boxes_[i].centre();
  }
  nodes_.reserve(2 * n / kLeafItems + 1);
  build(0, n, 0, centres);
  itemBoxes_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) itemBoxes_[i] = boxes_[items_[i]];
}

std::uint32_t QueryTree::build(std::uint32_t begin, std::uint32_t end, int depth, const std::vector<Vec3>& centres) {
  const auto self = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Aabb box, spread;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.grow(boxes_[items_[i]]);
    spread.grow(centres[items_[i]]);
  }
  nodes_[self].box = box;
  const std::uint32_t count = end - begin;
  const auto makeLeaf = [&] {
    nodes_[self].index = begin;
    nodes_[self].count = count;
    return self;
  };
  if (count <= kLeafItems) return makeLeaf();
  int axis = 0;
  spread.extents().maxCoeff(&axis);
  const double lo = spread.min[axis], width = spread.max[axis] - lo;
  std::uint32_t middle = begin + count / 2;
  const auto centreLess = [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; };
  if (!(width > 0.0) || depth >= kSahDepth) {
    if (count <= kMaxLeafItems && width == 0.0) return makeLeaf();
    std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end, centreLess);
  } else {
    // Binned SAH: the split between bins that minimises area x count on both sides.
    std::array<Aabb, kSahBins> bins;
    std::array<std::uint32_t, kSahBins> counts{};
    const double scale = kSahBins / width;
    const auto binOf = [&](std::uint32_t item) {
      return std::min(kSahBins - 1, static_cast<int>((centres[item][axis] - lo) * scale));
    };
    for (std::uint32_t i = begin; i < end; ++i) {
      const int b = binOf(items_[i]);
      bins[b].grow(boxes_[items_[i]]);
      ++counts[b];
    }
    std::array<double, kSahBins> rightCost{};
    Aabb right;
    std::uint32_t rightCount = 0;
    for (int b = kSahBins - 1; b > 0; --b) {
      right.grow(bins[b]);
      rightCount += counts[b];
      rightCost[b] = halfSurfaceArea(right) * rightCount;
    }
    Aabb left;
    std::uint32_t leftCount = 0;
    double best = std::numeric_limits<double>::infinity();
    int split = 1;
    for (int b = 1; b < kSahBins; ++b) {
      left.grow(bins[b - 1]);
      leftCount += counts[b - 1];
      const double cost = halfSurfaceArea(left) * leftCount + rightCost[b];
      if (cost < best) {
        best = cost;
        split = b;
      }
    }
    const double leafCost = halfSurfaceArea(box) * count;
    if (count <= kMaxLeafItems && kSahTraversalCost * halfSurfaceArea(box) + best >= leafCost) return makeLeaf();
    middle = static_cast<std::uint32_t>(
        std::partition(items_.begin() + begin, items_.begin() + end, [&](std::uint32_t item) { return binOf(item) < split; }) -
        items_.begin());
    if (middle == begin || middle == end) {
      middle = begin + count / 2;
      std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end, centreLess);
    }
  }
  build(begin, middle, depth + 1, centres);
  nodes_[self].index = build(middle, end, depth + 1, centres);
  return self;
}

std::shared_ptr<const QueryTree> queryTree(const World& world) {
  QueryTreeCache& cache = WorldAccess::queryCache(world);
  const std::lock_guard<std::mutex> lock(cache.mutex);
  if (!cache.tree || cache.version != geometryVersion(world)) {
    std::vector<Aabb> boxes(world.bodies().size());
    for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = queryBounds(world.bodies()[i]);
    auto tree = std::make_shared<QueryTree>(std::move(boxes));
    tree->proxies.resize(tree->items().size());
    for (std::size_t k = 0; k < tree->proxies.size(); ++k) {
      const RigidBody& body = world.bodies()[tree->items()[k]];
      RayProxy& proxy = tree->proxies[k];
      const ShapeType type = body.shape().type;
      proxy.closedForm = !body.isCompound() && type != ShapeType::ConvexHull && type != ShapeType::Mesh;
      if (!proxy.closedForm) continue;
      proxy.shape = body.shape();
      proxy.rotation = body.rotation();
      proxy.position = body.position();
      proxy.filter = body.filter();
    }
    cache.tree = std::move(tree);
    cache.version = geometryVersion(world);
  }
  return cache.tree;
}

QueryCacheSlot::QueryCacheSlot() : cache_(std::make_shared<QueryTreeCache>()) {}
QueryCacheSlot::QueryCacheSlot(const QueryCacheSlot&) : QueryCacheSlot() {}
QueryCacheSlot& QueryCacheSlot::operator=(const QueryCacheSlot&) {
  cache_ = std::make_shared<QueryTreeCache>();
  return *this;
}
QueryCacheSlot::~QueryCacheSlot() = default;

}  // namespace rbsim
