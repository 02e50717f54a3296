#include "collision/broadphase/sweep_and_prune.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "collision/broadphase/slab_mask.h"

namespace rbsim {
namespace {

constexpr int kAxes = 3;
// Tags are 2 id + 1 at most, in 32 bits.
constexpr std::size_t kMaxProxyIds = std::size_t{1} << 31;
// Slab width for the masks, in mean box extents: a box then covers one or two slabs, and two
// boxes far apart on an axis share a bit about a quarter of the time.
constexpr double kSlabWidthInExtents = 2.0;
constexpr std::uint32_t kLowByte = 0xffu, kSecondByte = 0xff00u;
constexpr std::size_t kInitialCrossings = 1024;  // entries; the buffer doubles when full

// 1 if the boxes whose 16 mask bits are a and b could overlap on both axes they describe, else 0.
std::uint32_t masksMeet(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t shared = a & b;
  return static_cast<std::uint32_t>((shared & kLowByte) != 0) &
         static_cast<std::uint32_t>((shared & kSecondByte) != 0);
}

}  // namespace

ProxyId SweepAndPrune::add(const Aabb& box, bool isStatic) {
  requireProxyBox(box);
  if (ids_.count() >= kMaxProxyIds) throw std::length_error("SweepAndPrune: too many proxies");
  const ProxyId id = ids_.acquire();
  if (id >= isStatic_.size()) {
    for (int k = 0; k < kAxes; ++k) {
      coord_[k].resize(2 * (std::size_t{id} + 1));
      prevCoord_[k].resize(coord_[k].size());
    }
    slabMasks_.resize(id + 1);
    for (auto* flags : {&isStatic_, &pendingAdd_, &stale_, &moved_}) flags->resize(id + 1);
  }
  for (int k = 0; k < kAxes; ++k) {
    coord_[k][2 * id] = box.min[k];
    coord_[k][2 * id + 1] = box.max[k];
  }
  updateSlabMasks(id);
  isStatic_[id] = isStatic;
  pendingAdd_[id] = 1;
  pendingAddIds_.push_back(id);
  return id;
}

void SweepAndPrune::remove(ProxyId id) {
  ids_.release(id);
  if (pendingAdd_[id]) {
    pendingAdd_[id] = 0;  // never sorted: nothing to drop
  } else {
    // Its endpoints and pairs go at the next update(); the id may be handed out again before
    // that, so the flag is by id and the new proxy's endpoints are only appended after the drop.
    stale_[id] = 1;
    staleIds_.push_back(id);
  }
}

void SweepAndPrune::move(ProxyId id, const Aabb& box) {
  ids_.requireAlive(id, "move");
  requireProxyBox(box);
  for (int k = 0; k < kAxes; ++k) {
    double& lo = coord_[k][2 * id];
    double& hi = coord_[k][2 * id + 1];
    if (!pendingAdd_[id]) travel_[k] += std::abs(0.5 * (box.min[k] + box.max[k]) - 0.5 * (lo + hi));
    lo = box.min[k];
    hi = box.max[k];
  }
  updateSlabMasks(id);
  if (!moved_[id]) {
    moved_[id] = 1;
    movedIds_.push_back(id);
  }
}

void SweepAndPrune::updateSlabMasks(ProxyId id) {
  std::uint32_t masks = 0;
  for (int k = 0; k < kAxes; ++k) {
    masks |= slabMask(coord_[k][2 * id], coord_[k][2 * id + 1], slabInvWidth_[k]) << (8 * k);
  }
  slabMasks_[id] = masks;
}

bool SweepAndPrune::overlaps(const Coords& c, ProxyId p, ProxyId q) {
  for (const std::vector<double>& axis : c) {
    if (axis[2 * p] > axis[2 * q + 1] || axis[2 * q] > axis[2 * p + 1]) return false;
  }
  return true;
}

void SweepAndPrune::update() {
  stats_ = {};
  dropRemoved();
  std::vector<ProxyId> added;
  for (ProxyId id : pendingAddIds_) {
    if (pendingAdd_[id]) added.push_back(id);  // skips proxies removed again before the update
    pendingAdd_[id] = 0;
  }
  pendingAddIds_.clear();

  const std::size_t endpointsAfter = axes_[0].size() + 2 * added.size();
  const double cost = rebuildCost(endpointsAfter);
  // After an update that found too many pairs (rebuild), the lists are sorted on boxes that pairs_
  // does not reflect: only a rebuild lists them again.
  const bool rebuildNow = overflowed_ || predictedSwaps(added.size()) > cost;
  appendAdded(added);
  travel_.setZero();
  if (rebuildNow) {
    stats_.path = Path::Rebuild;
    rebuild();
  } else {
    started_.clear();
    ended_.clear();
    crossingCount_ = 0;
    // If the prediction was wrong (say a tight cluster moving inside a wide scene), stop once
    // the swaps have cost as much as a rebuild: the worst case is then twice a rebuild, not n^2.
    const std::size_t swapBudget = static_cast<std::size_t>(cost);
    bool sorted = true;
    for (int k = 0; k < kAxes && sorted; ++k) sorted = sortAxis(k, swapBudget);
    // More pairs starting than a step may hold (some twice, from two axes): the rebuild counts
    // them exactly and refuses.
    if (sorted && processCrossings()) {
      mergeStartedAndEnded();
      if (pairs_.size() > kMaxBroadPhasePairs) {
        pairs_.clear();
        overflowed_ = true;
        throwPairLimit(ids_.count());
      }
    } else {
      stats_.path = Path::IncrementalAbandoned;
      rebuild();
    }
  }
  rememberBoxes(added);
}

// Every live proxy's box becomes the one pairs_ reflects (after the rebuild that follows an
// overflow, when the proxies added by the failed update were never remembered).
void SweepAndPrune::rememberAllBoxes() {
  for (int k = 0; k < kAxes; ++k) prevCoord_[k] = coord_[k];
  for (ProxyId id : movedIds_) moved_[id] = 0;
  movedIds_.clear();
}

// Removed proxies leave the lists in one pass per axis, and their pairs in one pass.
void SweepAndPrune::dropRemoved() {
  if (staleIds_.empty()) return;
  for (auto& list : axes_) {
    list.erase(std::remove_if(list.begin(), list.end(), [&](const Endpoint& e) { return stale_[e.id()] != 0; }),
               list.end());
  }
  pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(),
                              [&](const ProxyPair& p) { return stale_[p.a] != 0 || stale_[p.b] != 0; }),
               pairs_.end());
  for (ProxyId id : staleIds_) stale_[id] = 0;
  staleIds_.clear();
}

// New endpoints go at the end of each list, as if the proxy came from +infinity, where it
// overlapped nothing (zero masks for the last update): the insertion sort then moves them into
// place, starting their pairs.
void SweepAndPrune::appendAdded(const std::vector<ProxyId>& added) {
  for (int k = 0; k < kAxes; ++k) {
    for (ProxyId id : added) {
      for (std::uint32_t tag : {2 * id, 2 * id + 1}) axes_[k].push_back({coord_[k][tag], tag, 0});
    }
  }
}

// The previous boxes become the ones pairs_ now reflects.
void SweepAndPrune::rememberBoxes(const std::vector<ProxyId>& added) {
  const auto remember = [&](ProxyId id) {
    for (int k = 0; k < kAxes; ++k) {
      prevCoord_[k][2 * id] = coord_[k][2 * id];
      prevCoord_[k][2 * id + 1] = coord_[k][2 * id + 1];
    }
    moved_[id] = 0;
  };
  for (ProxyId id : movedIds_) remember(id);
  for (ProxyId id : added) remember(id);
  movedIds_.clear();
}

// Swaps the insertion sort is expected to make, with endpoints spread evenly over each list's
// range: a moved endpoint passes (endpoints per metre) x (distance moved); the 2k endpoints of k
// added proxies pass half of the E existing ones each, and each other about (2k)^2 / 4 times
// (the inversions of a random order), so k E + k^2 per axis.
double SweepAndPrune::predictedSwaps(std::size_t addedCount) const {
  const double existing = static_cast<double>(axes_[0].size());
  const double k = static_cast<double>(addedCount);
  double swaps = kAxes * (k * existing + k * k);
  for (int a = 0; a < kAxes; ++a) {
    if (axes_[a].empty() || travel_[a] == 0) continue;
    const double extent = axes_[a].back().value - axes_[a].front().value;  // [m], last update
    if (extent <= 0) return std::numeric_limits<double>::infinity();
    swaps += 2.0 * existing / extent * travel_[a];  // 2 endpoints per moved proxy
  }
  return swaps;
}

// A rebuild sorts each list from scratch (E log2 E comparisons) and sweeps one axis; the sweep's
// box tests are taken from the last rebuild, since they depend on how the boxes are spread.
double SweepAndPrune::rebuildCost(std::size_t endpointsPerAxis) const {
  const double e = static_cast<double>(std::max<std::size_t>(endpointsPerAxis, 2));
  return kAxes * e * std::log2(e) + static_cast<double>(lastSweepTests_);
}

// One insertion-sort pass over `axis`, refreshing each endpoint's value as it is reached: all
// values to its left are already the new ones, so every swap puts two endpoints into their final
// order. A swap of a min and a max whose masks meet is noted without a branch (whether it is one
// is a coin toss the processor cannot predict, and mispredictions cost more than the swap);
// processCrossings() tests the few noted. Returns false once the update's swaps exceed the budget.
bool SweepAndPrune::sortAxis(int axis, std::size_t swapBudget) {
  std::vector<Endpoint>& list = axes_[axis];
  if (crossings_.empty()) crossings_.resize(kInitialCrossings);
  for (std::size_t i = 0; i < list.size(); ++i) {
    Endpoint x = list[i];
    x.value = coord_[axis][x.tag];
    x.masks = masksOf(x.id(), axis) | x.masks << 16;  // last update's new masks become the old
    // A min passing a max may start a pair (compare new masks); a max passing a min may end one
    // (compare the masks of the last update).
    const std::uint32_t shift = (x.tag & 1u) << 4;
    std::size_t j = i;
    for (; j > 0 && before(x, list[j - 1]); --j) {
      const Endpoint& y = list[j - 1];
      crossings_[crossingCount_] = {x.tag, y.tag};
      crossingCount_ += ((x.tag ^ y.tag) & 1u) & masksMeet(x.masks >> shift, y.masks >> shift);
      if (crossingCount_ == crossings_.size()) crossings_.resize(2 * crossings_.size());
      list[j] = y;
    }
    list[j] = x;
    stats_.swaps += i - j;
    if (stats_.swaps > swapBudget) return false;
  }
  return true;
}

bool SweepAndPrune::processCrossings() {
  for (std::size_t c = 0; c < crossingCount_; ++c) {
    if (started_.size() == kMaxBroadPhasePairs) {
      crossingCount_ = 0;
      return false;
    }
    const ProxyId p = crossings_[c].moving >> 1, q = crossings_[c].passed >> 1;
    if ((crossings_[c].moving & 1u) == 0) {
      // p's min now precedes q's max: the intervals overlap on that axis; test all three.
      if (!(isStatic_[p] && isStatic_[q]) && overlaps(coord_, p, q)) started_.push_back(pairKey(p, q));
    } else if (overlaps(prevCoord_, p, q)) {
      // p's max now precedes q's min: apart on that axis. Only a pair whose boxes overlapped at
      // the last update can be listed.
      ended_.push_back(pairKey(p, q));
    }
  }
  crossingCount_ = 0;
  return true;
}

// pairs_ = (pairs_ - ended) + started, all sorted by key, in one pass.
void SweepAndPrune::mergeStartedAndEnded() {
  std::sort(started_.begin(), started_.end());
  started_.erase(std::unique(started_.begin(), started_.end()), started_.end());
  std::sort(ended_.begin(), ended_.end());
  merged_.clear();
  merged_.reserve(pairs_.size() + started_.size());
  std::size_t s = 0, e = 0;
  for (const ProxyPair& p : pairs_) {
    const std::uint64_t key = pairKey(p.a, p.b);
    for (; s < started_.size() && started_[s] < key; ++s) merged_.push_back(pairOfKey(started_[s]));
    if (s < started_.size() && started_[s] == key) ++s;  // already listed: keep one copy
    while (e < ended_.size() && ended_[e] < key) ++e;
    if (e < ended_.size() && ended_[e] == key) continue;
    merged_.push_back(p);
  }
  for (; s < started_.size(); ++s) merged_.push_back(pairOfKey(started_[s]));
  pairs_.swap(merged_);
}

void SweepAndPrune::rebuild() {
  // New slab widths from the mean box extents; every mask is redone, old and new alike.
  Vec3 extentSum = Vec3::Zero();
  for (const Endpoint& e : axes_[0]) {
    if (e.isMax()) continue;
    for (int k = 0; k < kAxes; ++k) extentSum[k] += coord_[k][e.tag + 1] - coord_[k][e.tag];
  }
  const double proxies = 0.5 * static_cast<double>(axes_[0].size());
  for (int k = 0; k < kAxes; ++k) {
    const double width = kSlabWidthInExtents * extentSum[k] / std::max(proxies, 1.0);  // [m]
    slabInvWidth_[k] = width > 0 && std::isfinite(1.0 / width) ? 1.0 / width : 1.0;
  }
  for (const Endpoint& e : axes_[0]) {
    if (!e.isMax()) updateSlabMasks(e.id());
  }
  for (int k = 0; k < kAxes; ++k) {
    for (Endpoint& e : axes_[k]) {
      e.value = coord_[k][e.tag];
      const std::uint32_t masks = masksOf(e.id(), k);
      e.masks = masks | masks << 16;
    }
    std::sort(axes_[k].begin(), axes_[k].end(), before);
  }
  // Sweep the axis along which the box centres spread most: it has the fewest overlapping
  // intervals, so the fewest candidate pairs to test (Ericson §7.5.2).
  Vec3 sum = Vec3::Zero(), sumSq = Vec3::Zero();
  for (const Endpoint& e : axes_[0]) {
    if (e.isMax()) continue;
    for (int k = 0; k < kAxes; ++k) {
      const double twiceCentre = coord_[k][e.tag] + coord_[k][e.tag + 1];  // same argmax
      sum[k] += twiceCentre;
      sumSq[k] += twiceCentre * twiceCentre;
    }
  }
  int axis = 0;
  (sumSq - sum.cwiseProduct(sum) / std::max(proxies, 1.0)).maxCoeff(&axis);
  const int u = (axis + 1) % kAxes, v = (axis + 2) % kAxes;

  // Proxies whose min has been passed and whose max has not: their intervals on `axis` contain
  // the current endpoint, so each new min is tested against them on the other two axes only.
  struct Active {
    double minU, maxU, minV, maxV;  // [m]
    ProxyId id;
    bool isStatic;
  };
  std::vector<Active> active;
  std::vector<std::uint32_t> activeSlot(isStatic_.size());
  started_.clear();
  std::size_t tests = 0;
  for (const Endpoint& e : axes_[axis]) {
    const ProxyId id = e.id();
    if (e.isMax()) {
      const std::uint32_t s = activeSlot[id];
      active[s] = active.back();
      activeSlot[active[s].id] = s;
      active.pop_back();
      continue;
    }
    const Active me{coord_[u][e.tag], coord_[u][e.tag + 1], coord_[v][e.tag], coord_[v][e.tag + 1],
                    id, isStatic_[id] != 0};
    tests += active.size();
    for (const Active& o : active) {
      // One branch, on a rarely true result: separate tests would each be mispredicted often.
      const bool hit = (me.minU <= o.maxU) & (o.minU <= me.maxU) & (me.minV <= o.maxV) & (o.minV <= me.maxV) &
                       !(me.isStatic & o.isStatic);
      if (!hit) continue;
      if (started_.size() == kMaxBroadPhasePairs) {
        // Refused before listing more; the next update() rebuilds (overflowed_).
        started_.clear();
        pairs_.clear();
        overflowed_ = true;
        throwPairLimit(ids_.count());
      }
      started_.push_back(pairKey(id, o.id));
    }
    activeSlot[id] = static_cast<std::uint32_t>(active.size());
    active.push_back(me);
  }
  stats_.sweepTests = tests;
  lastSweepTests_ = tests;
  if (overflowed_) {
    overflowed_ = false;
    rememberAllBoxes();
  }
  std::sort(started_.begin(), started_.end());
  pairs_.clear();
  pairs_.reserve(started_.size());
  for (std::uint64_t key : started_) pairs_.push_back(pairOfKey(key));
}

}  // namespace rbsim
