#include "world/split_broad_phase.h"

#include <algorithm>

#include "collision/broadphase/brute_force.h"
#include "collision/broadphase/sweep_and_prune.h"
#include "world/query_tree.h"

namespace rbsim {

namespace {

// The tree is built anew when the proxies come to rest since its build, each of which every
// awake box tests one by one, cost more tests a step than kRebuildShare of its items would (a
// build costs about a box query of each item), or half its items have woken or gone.
constexpr std::size_t kRebuildShare = 8;
constexpr std::size_t kExtraSlack = 16;  // [proxies] resting outside the tree before any rebuild

std::unique_ptr<BroadPhase> makeAwakeBroadPhase(Settings::BroadPhaseMethod method) {
  if (method == Settings::BroadPhaseMethod::BruteForce) return std::make_unique<BruteForce>();
  return std::make_unique<SweepAndPrune>();
}

}  // namespace

SplitBroadPhase::SplitBroadPhase(Settings::BroadPhaseMethod method) : method_(method), awake_(makeAwakeBroadPhase(method)) {}

SplitBroadPhase::SplitBroadPhase(const SplitBroadPhase& other)
    : method_(other.method_),
      ids_(other.ids_),
      box_(other.box_),
      awake_(other.awake_->clone()),
      inAwake_(other.inAwake_),
      proxyOfAwake_(other.proxyOfAwake_),
      awakeMembers_(other.awakeMembers_),
      stamp_(other.stamp_),
      updates_(other.updates_),
      tree_(other.tree_),
      treeItems_(other.treeItems_),
      inTree_(other.inTree_),
      inExtra_(other.inExtra_),
      extra_(other.extra_),
      treeLeft_(other.treeLeft_),
      treeDirty_(other.treeDirty_),
      pairs_(other.pairs_) {}

SplitBroadPhase::~SplitBroadPhase() = default;

ProxyId SplitBroadPhase::add(const Aabb& box) {
  requireProxyBox(box);
  const ProxyId id = ids_.acquire();
  if (box_.size() <= id) {
    box_.resize(id + 1);
    inAwake_.resize(id + 1, kNone);
    stamp_.resize(id + 1, 0);
    inTree_.resize(id + 1, 0);
    inExtra_.resize(id + 1, 0);
  }
  box_[id] = box;
  inAwake_[id] = kNone;
  // A reused id may still be named by the tree: it is built anew before the next query.
  if (inTree_[id] != 0) treeDirty_ = true;
  rest(id);
  return id;
}

void SplitBroadPhase::remove(ProxyId id) {
  ids_.requireAlive(id, "remove");
  if (inAwake_[id] != kNone) {
    awake_->remove(inAwake_[id]);
    inAwake_[id] = kNone;
    awakeMembers_.erase(std::find(awakeMembers_.begin(), awakeMembers_.end(), id));
  }
  if (inTree_[id] != 0) ++treeLeft_;
  ids_.release(id);
}

void SplitBroadPhase::move(ProxyId id, const Aabb& box) {
  box_[id] = box;
  if (inAwake_[id] != kNone) awake_->move(inAwake_[id], box);
}

void SplitBroadPhase::rest(ProxyId id) {
  if (inTree_[id] != 0 && !treeDirty_) {
    --treeLeft_;  // its tree item holds again
    return;
  }
  if (inExtra_[id] != 0) return;
  inExtra_[id] = 1;
  extra_.push_back(id);
}

void SplitBroadPhase::rest(const std::vector<ProxyId>& asleep) {
  if (asleep.empty()) return;
  for (const ProxyId id : asleep) {
    if (inAwake_[id] == kNone) continue;
    awake_->remove(inAwake_[id]);
    inAwake_[id] = kNone;
    rest(id);
  }
  awakeMembers_.erase(std::remove_if(awakeMembers_.begin(), awakeMembers_.end(), [&](ProxyId id) { return inAwake_[id] == kNone; }),
                      awakeMembers_.end());
}

void SplitBroadPhase::rebuildTree() {
  for (const ProxyId id : treeItems_) {
    if (id < inTree_.size()) inTree_[id] = 0;
  }
  for (const ProxyId id : extra_) inExtra_[id] = 0;
  extra_.clear();
  treeItems_.clear();
  std::vector<Aabb> boxes;
  for (ProxyId id = 0; id < ids_.capacity(); ++id) {
    if (!isResting(id)) continue;
    treeItems_.push_back(id);
    boxes.push_back(box_[id]);
    inTree_[id] = 1;
  }
  tree_ = boxes.empty() ? nullptr : std::make_shared<const QueryTree>(std::move(boxes));
  treeLeft_ = 0;
  treeDirty_ = false;
}

template <typename Visit>
void SplitBroadPhase::forEachResting(const Aabb& box, Visit&& visit) const {
  if (tree_) {
    tree_->walkBox(box, [&](std::uint32_t item) {
      const ProxyId id = treeItems_[item];
      if (isResting(id)) visit(id);
    });
  }
  for (const ProxyId id : extra_) {
    if (isResting(id) && box_[id].overlaps(box)) visit(id);
  }
}

void SplitBroadPhase::update(const std::vector<ProxyId>& awake) {
  ++updates_;
  // The proxies awake now join awake_; those no longer awake leave it and rest.
  for (const ProxyId id : awake) {
    stamp_[id] = updates_;
    if (inAwake_[id] != kNone) continue;
    const ProxyId inner = awake_->add(box_[id], false);
    inAwake_[id] = inner;
    if (proxyOfAwake_.size() <= inner) proxyOfAwake_.resize(inner + 1);
    proxyOfAwake_[inner] = id;
    awakeMembers_.push_back(id);
    if (inTree_[id] != 0 && !treeDirty_) ++treeLeft_;
  }
  std::size_t kept = 0;
  for (const ProxyId id : awakeMembers_) {
    if (stamp_[id] == updates_) {
      awakeMembers_[kept++] = id;
      continue;
    }
    awake_->remove(inAwake_[id]);
    inAwake_[id] = kNone;
    rest(id);
  }
  awakeMembers_.resize(kept);
  awake_->update();
  const std::size_t treeSize = treeItems_.size();
  if (treeDirty_ || 2 * treeLeft_ > treeSize + kExtraSlack ||
      (extra_.size() > kExtraSlack && extra_.size() * awakeMembers_.size() > treeSize / kRebuildShare)) {
    rebuildTree();
  }
  pairs_.clear();
  for (const ProxyPair& p : awake_->pairs()) {
    const ProxyId a = proxyOfAwake_[p.a], b = proxyOfAwake_[p.b];
    pairs_.push_back(a < b ? ProxyPair{a, b} : ProxyPair{b, a});
  }
  for (const ProxyId id : awakeMembers_) {
    forEachResting(box_[id], [&](ProxyId other) { pairs_.push_back(id < other ? ProxyPair{id, other} : ProxyPair{other, id}); });
    if (pairs_.size() > kMaxBroadPhasePairs) {
      pairs_.clear();
      throwPairLimit(ids_.count());
    }
  }
  // Already in order when the awake set's ids follow the proxies' and nothing rests nearby (a
  // scene where nothing sleeps): the check spares the sort.
  if (!std::is_sorted(pairs_.begin(), pairs_.end())) std::sort(pairs_.begin(), pairs_.end());
}

void SplitBroadPhase::resting(const Aabb& box, std::vector<ProxyId>& out) const {
  forEachResting(box, [&](ProxyId id) { out.push_back(id); });
}

}  // namespace rbsim
