#pragma once
// Incremental sweep and prune (seed 004 "two-phase collision detection": exploit inter-frame
// coherence for near O(n) broad phase; Cohen, Lin, Manocha, Ponamgi, "I-COLLIDE", ACM I3D 1995).
//
// Each axis keeps a list of the proxies' box endpoints, sorted by (value, min before max). Closed
// intervals [min_i, max_i] and [min_j, max_j] overlap exactly when min_i precedes max_j and min_j
// precedes max_i in that order, because a min sorts before a max of equal value: touching boxes
// overlap, as in Aabb::overlaps. Between steps the lists are re-sorted by insertion sort, which
// costs O(n + swaps) and, the motion being coherent, swaps are few. Only a min passing a max
// changes whether two intervals overlap, so the pairs are updated as the sort swaps endpoints:
//  - a min moving before another proxy's max: the intervals start to overlap on this axis; if
//    the two new boxes overlap on all three axes (and are not both static), the pair starts;
//  - a max moving before another proxy's min: the intervals separate; if the boxes of the last
//    update overlapped (the pair is listed), the pair ends.
// Insertion sort swaps each pair of endpoints at most once and only into their final order, so a
// pair that ends is separated in the new boxes and never also starts: the new pair list is the
// old one minus the ended pairs plus the started ones, a linear merge of sorted lists.
// Most crossings are of boxes far apart on the other two axes; each endpoint carries slab masks
// (slab_mask.h) of its box on those axes, new and at the last update, which reject most of
// them without reading a box (at 5e4 boxes this halves the update time).
//
// Removed proxies leave the lists, and their pairs, in one pass at the next update(); added
// ones are appended to the lists and sorted in like moved ones. Static proxies are sorted like
// the rest (unmoved, they cost one comparison per update) but a static-static pair never starts.
//
// The fallback rule: update() predicts the insertion sort's swaps from the distances moved and
// the proxies added, assuming endpoints spread evenly over each list's range, and compares them
// with the cost of a rebuild, 3 E log2 E for E endpoints per axis plus the last rebuild's sweep
// tests. If the prediction is larger (many proxies added at once, or most proxies jumping far),
// it rebuilds: std::sort each list, then one sweep along the axis of largest spread (Ericson,
// Real-Time Collision Detection, 2005, §7.5.2). If the sort's actual swaps pass that cost (say a
// tight cluster stirring inside a wide scene), it is abandoned for a rebuild, so an update never
// costs much more than two rebuilds.
#include <array>
#include <cstdint>
#include <vector>

#include "rbsim/collision/broadphase/broad_phase.h"
#include "collision/broadphase/proxy_ids.h"

namespace rbsim {

class SweepAndPrune final : public BroadPhase {
 public:
  ProxyId add(const Aabb& box, bool isStatic = false) override;
  void remove(ProxyId id) override;
  void move(ProxyId id, const Aabb& box) override;
  void update() override;
  const std::vector<ProxyPair>& pairs() const override { return pairs_; }
  std::unique_ptr<BroadPhase> clone() const override { return std::make_unique<SweepAndPrune>(*this); }
  std::size_t proxyCount() const override { return ids_.count(); }

  // How the last update() went: which path it took and what it cost. For tests and benchmarks.
  enum class Path { Incremental, Rebuild, IncrementalAbandoned };
  struct UpdateStats {
    Path path = Path::Incremental;
    std::size_t swaps = 0;       // endpoint swaps done by the insertion sort
    std::size_t sweepTests = 0;  // box tests done by a rebuild's sweep
  };
  const UpdateStats& lastUpdate() const { return stats_; }

 private:
  // An endpoint's tag is 2 id + (1 if max). Its masks, in a list sorted on axis a, are the slab
  // masks of its box on axes a + 1 and a + 2 (mod 3): bits 0-15 for the new box, 16-31 for the
  // box at the last update().
  struct Endpoint {
    double value;  // [m] the coordinate, copied here so the sort compares without indirection
    std::uint32_t tag;
    std::uint32_t masks;
    ProxyId id() const { return tag >> 1; }
    bool isMax() const { return (tag & 1u) != 0; }
  };
  // 16 bytes, 4 endpoints a cache line: the insertion sort walks each axis's list every update,
  // comparing values and masks without leaving it.
  static_assert(sizeof(Endpoint) == 16, "Endpoint's size: see the comment above");
  static bool before(const Endpoint& x, const Endpoint& y) {
    return x.value < y.value || (x.value == y.value && x.isMax() < y.isMax());
  }
  // Coordinates by axis and tag [m]: coord[k][2 id] is the box's min on axis k, coord[k][2 id + 1]
  // its max. The sort reads one axis for every endpoint, in the list's (not the ids') order, so
  // one axis per array keeps what it reads small enough to stay in cache (16 bytes per proxy).
  using Coords = std::array<std::vector<double>, 3>;
  static bool overlaps(const Coords& c, ProxyId p, ProxyId q);
  void updateSlabMasks(ProxyId id);
  // The new box's 16 mask bits for a list sorted on `axis`.
  std::uint32_t masksOf(ProxyId id, int axis) const {
    const std::uint32_t m = slabMasks_[id];
    return (m >> (8 * ((axis + 1) % 3)) & 0xffu) | (m >> (8 * ((axis + 2) % 3)) & 0xffu) << 8;
  }

  void dropRemoved();
  void appendAdded(const std::vector<ProxyId>& added);
  double predictedSwaps(std::size_t addedCount) const;
  double rebuildCost(std::size_t endpointsPerAxis) const;
  bool sortAxis(int axis, std::size_t swapBudget);
  bool processCrossings();  // false: more pairs started than a step may hold
  void mergeStartedAndEnded();
  void rebuild();
  void rememberBoxes(const std::vector<ProxyId>& added);
  void rememberAllBoxes();

  ProxyIdPool ids_;
  Coords coord_;      // the box given to add() or the last move()
  Coords prevCoord_;  // the box at the last update(), which pairs_ reflects
  std::vector<std::uint32_t> slabMasks_;  // by id: byte k is the current box's mask on axis k
  std::vector<std::uint8_t> isStatic_;    // by id
  std::vector<std::uint8_t> pendingAdd_;  // by id: added since the last update(), not yet sorted
  std::vector<std::uint8_t> stale_;       // by id: removed since the last update(), still sorted
  std::vector<std::uint8_t> moved_;       // by id: moved since the last update()
  std::vector<ProxyId> pendingAddIds_, staleIds_, movedIds_;
  Vec3 travel_ = Vec3::Zero();  // [m] sum over moves since the last update() of |centre change|

  std::array<std::vector<Endpoint>, 3> axes_;  // sorted endpoint lists, one per axis
  // A min and a max of different proxies swapped by the sort, whose masks meet (tags).
  struct Crossing {
    std::uint32_t moving, passed;
  };
  static_assert(sizeof(Crossing) == 8, "two tags, 8 crossings a cache line");
  std::vector<Crossing> crossings_;  // the first crossingCount_ are this update's
  std::size_t crossingCount_ = 0;
  std::vector<std::uint64_t> started_, ended_;  // pair keys seen by the current update()
  std::vector<ProxyPair> pairs_, merged_;
  std::size_t lastSweepTests_ = 0;
  bool overflowed_ = false;  // the last update() found too many pairs: the next one rebuilds
  Vec3 slabInvWidth_ = Vec3::Ones();  // [1/m] for the masks; changes only when all are redone

  UpdateStats stats_;
};

}  // namespace rbsim
