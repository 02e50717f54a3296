#pragma once
// The World's broad phase (issue 58, "no scan of every body"): the pairs with an awake proxy,
// at a cost of the awake proxies, not of all. As Box2D v3 keeps its sleeping and static proxies in
// trees that only moved proxies query (src/broad_phase.c b2UpdateBroadPhasePairs, the move
// buffer), the awake proxies are kept in the chosen BroadPhase (sweep and prune, or brute force),
// which gives the awake-awake pairs, and the resting ones (static, or asleep) in a bounding
// volume hierarchy (world/query_tree.h) that each awake box queries. The tree is built anew when
// enough has changed since (bodies falling asleep wait in a short list until then; woken ones
// are skipped), never re-sorted or re-transformed by a step. The pairs are exactly those of the
// boxes, sorted by (a, b), as BroadPhase::pairs() would list them but for resting pairs.
//
// Ids are the World's stable proxy ids, handed out smallest free first (ProxyIdPool), so that a
// saved World read back names its proxies alike.
#include <cstdint>
#include <memory>
#include <vector>

#include "collision/broadphase/proxy_ids.h"
#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/settings/settings.h"

namespace rbsim {

class QueryTree;

class SplitBroadPhase {
 public:
  explicit SplitBroadPhase(Settings::BroadPhaseMethod method);
  SplitBroadPhase(const SplitBroadPhase& other);  // deep
  SplitBroadPhase& operator=(const SplitBroadPhase&) = delete;
  ~SplitBroadPhase();

  ProxyId add(const Aabb& box);  // resting until update() finds it awake
  void remove(ProxyId id);
  void move(ProxyId id, const Aabb& box);  // an awake proxy's box for this update
  // `awake`: the proxies awake now (those of the awake bodies); every other live one rests. Then
  // the pairs with an awake proxy. Throws StepLimitError past kMaxBroadPhasePairs.
  void update(const std::vector<ProxyId>& awake);
  const std::vector<ProxyPair>& pairs() const { return pairs_; }
  // Into `out`: the resting proxies whose box overlaps `box`, as of the last update().
  void resting(const Aabb& box, std::vector<ProxyId>& out) const;
  // Awake proxies whose bodies fell asleep at the end of a step rest now, not at the next
  // update(), so that nothing before it (a removal) visits them as awake.
  void rest(const std::vector<ProxyId>& asleep);
  // The proxies awake at the last update() (some may have fallen asleep since).
  const std::vector<ProxyId>& awakeAtUpdate() const { return awakeMembers_; }
  std::size_t capacity() const { return ids_.capacity(); }
  const Aabb& box(ProxyId id) const { return box_[id]; }

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  bool isResting(ProxyId id) const { return ids_.alive(id) && inAwake_[id] == kNone; }
  void rest(ProxyId id);  // it leaves the awake broad phase, or is new
  void rebuildTree();
  template <typename Visit>
  void forEachResting(const Aabb& box, Visit&& visit) const;

  Settings::BroadPhaseMethod method_;
  ProxyIdPool ids_;
  std::vector<Aabb> box_;                // per proxy: the last box given
  std::unique_ptr<BroadPhase> awake_;    // the awake proxies, under ids of its own
  std::vector<std::uint32_t> inAwake_;   // per proxy: its id in awake_, or kNone (resting)
  std::vector<ProxyId> proxyOfAwake_;    // per awake_ id: the proxy
  std::vector<ProxyId> awakeMembers_;    // the proxies in awake_
  std::vector<std::uint64_t> stamp_;     // per proxy: the update() that last found it awake
  std::uint64_t updates_ = 0;
  std::shared_ptr<const QueryTree> tree_;  // over treeItems_ (immutable, shared by copies)
  std::vector<ProxyId> treeItems_;       // per tree item: its proxy
  std::vector<char> inTree_, inExtra_;   // per proxy
  std::vector<ProxyId> extra_;           // resting proxies since the tree was built
  std::size_t treeLeft_ = 0;             // tree items that woke or went since it was built
  bool treeDirty_ = true;                // ids were reused: build before the next query
  std::vector<ProxyPair> pairs_;
};

}  // namespace rbsim
