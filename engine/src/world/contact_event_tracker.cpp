#include "world/contact_event_tracker.h"

#include <algorithm>
#include <string>

#include "math/byte_stream.h"
#include "rbsim/world/world.h"
#include "world/collision_pipeline.h"
#include "world/world_access.h"

namespace rbsim {

namespace {

constexpr std::uint64_t kPlaneBit = std::uint64_t{1} << 63;  // plane pairs after body pairs, as listed
constexpr std::uint64_t kChildMask = 0xffff;

std::uint64_t secondAndChildren(std::uint64_t second, std::uint16_t childFirst, std::uint16_t childSecond) {
  return (second << 32) | (std::uint64_t{childFirst} << 16) | std::uint64_t{childSecond};
}

// The deepest point of a manifold with points.
int deepest(const ContactManifold& m) {
  int k = 0;
  for (int i = 1; i < m.count; ++i) {
    if (m.points[i].depth > m.points[k].depth) k = i;
  }
  return k;
}

ContactPair pairOfContact(const Contact& c, const World& world) {
  ContactPair pair;
  if (c.kind == Contact::Kind::PlaneBody) {
    pair.plane = static_cast<std::int64_t>(c.a);
  } else {
    pair.bodyA = world.idAt(c.a);
  }
  pair.bodyB = world.idAt(c.b);
  pair.childA = c.childA;
  pair.childB = c.childB;
  if (c.kind != Contact::Kind::PlaneBody) pair.shapeA = WorldAccess::shapeIdOf(world, c.a, c.childA);
  pair.shapeB = WorldAccess::shapeIdOf(world, c.b, c.childB);
  return pair;
}

bool samePair(const ContactPair& x, const ContactPair& y) {
  return x.bodyA == y.bodyA && x.bodyB == y.bodyB && x.plane == y.plane && x.childA == y.childA && x.childB == y.childB;
}

}  // namespace

ContactEventTracker::Entry ContactEventTracker::keyOf(const Contact& c, const CollisionPipeline& collision) {
  Entry e;
  if (c.kind == Contact::Kind::PlaneBody) {
    e.hi = kPlaneBit | std::uint64_t{c.a};
    e.lo = secondAndChildren(collision.proxyOf(c.b), c.childA, c.childB);
    return e;
  }
  const std::uint64_t pa = collision.proxyOf(c.a), pb = collision.proxyOf(c.b);
  e.swapped = pb < pa;
  e.hi = e.swapped ? pb : pa;
  e.lo = e.swapped ? secondAndChildren(pa, c.childB, c.childA) : secondAndChildren(pb, c.childA, c.childB);
  return e;
}

ContactPair ContactEventTracker::pairOf(const Entry& e, const World& world, const CollisionPipeline& collision) const {
  ContactPair pair;
  const auto first = static_cast<std::uint16_t>((e.lo >> 16) & kChildMask);
  const auto second = static_cast<std::uint16_t>(e.lo & kChildMask);
  const std::size_t secondIndex = collision.bodyOfProxy(static_cast<ProxyId>(e.lo >> 32));
  if ((e.hi & kPlaneBit) != 0) {
    pair.plane = static_cast<std::int64_t>(e.hi & ~kPlaneBit);
    pair.bodyB = world.idAt(secondIndex);
    pair.childA = first;
    pair.childB = second;
    pair.shapeB = WorldAccess::shapeIdOf(world, secondIndex, second);
    return pair;
  }
  const std::size_t lowIndex = collision.bodyOfProxy(static_cast<ProxyId>(e.hi));
  const std::size_t highIndex = secondIndex;
  const BodyId low = world.idAt(lowIndex);
  const BodyId high = world.idAt(highIndex);
  pair.bodyA = e.swapped ? high : low;
  pair.bodyB = e.swapped ? low : high;
  pair.childA = e.swapped ? second : first;
  pair.childB = e.swapped ? first : second;
  pair.shapeA = WorldAccess::shapeIdOf(world, e.swapped ? highIndex : lowIndex, pair.childA);
  pair.shapeB = WorldAccess::shapeIdOf(world, e.swapped ? lowIndex : highIndex, pair.childB);
  return pair;
}

bool ContactEventTracker::asleep(const Entry& e, const World& world, const CollisionPipeline& collision) const {
  const std::vector<RigidBody>& bodies = world.bodies();
  const std::size_t second = collision.bodyOfProxy(static_cast<ProxyId>(e.lo >> 32));
  if ((e.hi & kPlaneBit) != 0) return !bodies[second].awake();
  return !bodies[collision.bodyOfProxy(static_cast<ProxyId>(e.hi))].awake() && !bodies[second].awake();
}

void ContactEventTracker::beginStep() {
  haveNext_ = false;
  step_.clear();
}

void ContactEventTracker::afterNarrowPhase(const World& world, const CollisionPipeline& collision) {
  const std::vector<Contact>& contacts = collision.contacts();
  keys_.clear();
  bool sorted = true;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (contacts[i].manifold.count == 0) continue;
    Entry e = keyOf(contacts[i], collision);
    e.contact = static_cast<std::uint32_t>(i);
    if (!keys_.empty() && e < keys_.back()) sorted = false;
    keys_.push_back(e);
  }
  // Out of order when a pair's proxies are not in its contact's order (bodies ordered by their
  // keys, CollisionPipeline::bodiesOf, whose proxies a removal may have reused): the list order is
  // kept among equal keys (a grid pair's several manifolds), so the first is the one reported.
  if (!sorted) std::stable_sort(keys_.begin(), keys_.end());
  next_.clear();
  std::size_t i = 0, j = 0;
  while (i < touching_.size() || j < keys_.size()) {
    if (j < keys_.size() && j > 0 && keys_[j].sameKey(keys_[j - 1])) {
      ++j;  // a further manifold of the same pair of shapes
      continue;
    }
    if (j == keys_.size() || (i < touching_.size() && touching_[i] < keys_[j])) {
      const Entry& was = touching_[i++];
      if (asleep(was, world, collision)) {
        Entry kept = was;
        kept.contact = kNoContact;
        asleep_[{kept.hi, kept.lo}] = kept;
      } else {
        step_.end.push_back({pairOf(was, world, collision)});
      }
      continue;
    }
    Entry now = keys_[j++];
    const auto kept = asleep_.empty() ? asleep_.end() : asleep_.find({now.hi, now.lo});
    if (i < touching_.size() && touching_[i].sameKey(now)) {
      now.swapped = touching_[i].swapped;  // named as its begin named it
      now.hit = touching_[i++].hit;
    } else if (kept != asleep_.end()) {  // woken without contactsWoke (a removal's renumbering)
      now.swapped = kept->second.swapped;
      now.hit = kept->second.hit;
      asleep_.erase(kept);
    } else {
      const Contact& c = contacts[now.contact];
      const ContactPoint& p = c.manifold.points[deepest(c.manifold)];
      step_.begin.push_back({pairOfContact(c, world), p.position, c.manifold.normal, p.depth});
    }
    next_.push_back(now);
  }
  haveNext_ = true;
}

void ContactEventTracker::afterSolve(const World& world, const CollisionPipeline& collision,
                                     const std::vector<Contact>& contacts, const ContactSolver& solver, double speed) {
  hits_.clear();
  solver.hits(speed, hits_);
  if (hits_.empty()) return;
  if (!haveNext_) {  // no narrow phase this step: the pairs are the last step's
    next_ = touching_;
    haveNext_ = true;
  }
  std::size_t firstNew = step_.hit.size();
  for (const ContactHit& hit : hits_) {
    const Contact& c = contacts[hit.contact];
    const Entry key = keyOf(c, collision);
    const auto at = std::lower_bound(next_.begin(), next_.end(), key);
    if (at == next_.end() || !at->sameKey(key)) continue;  // not touching (cannot be: it was solved)
    const ContactHitEvent event{pairOfContact(c, world), hit.point, c.manifold.normal, hit.approachSpeed};
    // A grid pair's several manifolds are one pair of shapes: its fastest point.
    if (step_.hit.size() > firstNew && samePair(step_.hit.back().pair, event.pair)) {
      if (event.approachSpeed > step_.hit.back().approachSpeed) step_.hit.back() = event;
      continue;
    }
    if (at->hit) continue;
    at->hit = true;
    step_.hit.push_back(event);
  }
}

template <typename Names>
void ContactEventTracker::takeWhere(std::vector<Entry>& list, const CollisionPipeline& collision, Names&& names,
                                    std::vector<Entry>& taken) {
  std::size_t kept = 0;
  for (const Entry& e : list) {
    const std::size_t second = collision.bodyOfProxy(static_cast<ProxyId>(e.lo >> 32));
    const bool plane = (e.hi & kPlaneBit) != 0;
    const bool named = names(second) || (!plane && names(collision.bodyOfProxy(static_cast<ProxyId>(e.hi))));
    if (named) {
      taken.push_back(e);
    } else {
      list[kept++] = e;
    }
  }
  list.resize(kept);
}

void ContactEventTracker::bodyBroken(const World& world, const CollisionPipeline& collision, std::size_t index) {
  if (!haveNext_) {  // no narrow phase this step: the pairs are the last step's
    next_ = touching_;
    haveNext_ = true;
  }
  std::vector<Entry> ending;
  takeWhere(next_, collision, [index](std::size_t body) { return body == index; }, ending);
  for (const Entry& e : ending) step_.end.push_back({pairOf(e, world, collision)});
}

void ContactEventTracker::bodiesRemoving(const World& world, const CollisionPipeline& collision,
                                         const std::vector<std::uint32_t>& gone) {
  const auto named = [&gone](std::size_t body) { return std::binary_search(gone.begin(), gone.end(), body); };
  std::vector<Entry> ending;
  takeWhere(touching_, collision, named, ending);
  // The asleep pairs of the removed bodies, found from their kept contacts: no other asleep pair
  // is visited (issue 58: removal costs what it touches).
  std::vector<Contact> kept;
  collision.keptContactsOf(gone, kept);
  for (const Contact& c : kept) {
    const Entry key = keyOf(c, collision);
    const auto at = asleep_.find({key.hi, key.lo});
    if (at == asleep_.end()) continue;  // a grid pair's further manifold, or not touching
    ending.push_back(at->second);
    asleep_.erase(at);
  }
  std::sort(ending.begin(), ending.end());  // in key order, as the pairs are listed
  for (const Entry& e : ending) queuedEnds_.push_back({pairOf(e, world, collision)});
}

void ContactEventTracker::commit() {
  if (haveNext_) touching_.swap(next_);
  haveNext_ = false;
  events_.begin.swap(step_.begin);
  events_.hit.swap(step_.hit);
  events_.end.clear();
  events_.end.insert(events_.end.end(), queuedEnds_.begin(), queuedEnds_.end());
  events_.end.insert(events_.end.end(), step_.end.begin(), step_.end.end());
  queuedEnds_.clear();
  step_.clear();
}

void ContactEventTracker::contactsWoke(const std::vector<Contact>& contacts, const CollisionPipeline& collision) {
  if (asleep_.empty()) return;
  std::vector<Entry>& list = haveNext_ ? next_ : touching_;
  const std::size_t first = list.size();
  for (const Contact& c : contacts) {
    const Entry key = keyOf(c, collision);
    const auto at = asleep_.find({key.hi, key.lo});
    if (at == asleep_.end()) continue;
    list.push_back(at->second);
    asleep_.erase(at);
  }
  std::sort(list.begin() + static_cast<std::ptrdiff_t>(first), list.end());
  std::inplace_merge(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(first), list.end());
}

void ContactEventTracker::contactsSlept(const std::vector<Contact>& contacts, const CollisionPipeline& collision,
                                        const std::vector<std::uint32_t>& newIndex) {
  std::vector<Entry>& list = haveNext_ ? next_ : touching_;
  std::vector<Entry> slept;
  slept.reserve(contacts.size());
  for (const Contact& c : contacts) slept.push_back(keyOf(c, collision));
  std::sort(slept.begin(), slept.end());
  std::size_t kept = 0;
  for (Entry& e : list) {
    const auto at = std::lower_bound(slept.begin(), slept.end(), e);
    if (at != slept.end() && at->sameKey(e)) {
      e.contact = kNoContact;
      asleep_[{e.hi, e.lo}] = e;
      continue;
    }
    if (e.contact != kNoContact && e.contact < newIndex.size()) e.contact = newIndex[e.contact];
    list[kept++] = e;
  }
  list.resize(kept);
}

// The asleep pairs with the others, in one list sorted by key: read back into touching_, the
// next afterNarrowPhase keeps them aside again.
void ContactEventTracker::save(ByteWriter& out) const {
  std::vector<Entry> all = touching_;
  for (const auto& [key, entry] : asleep_) all.push_back(entry);
  std::sort(all.begin(), all.end());
  out.count(all.size());
  for (const Entry& e : all) {
    out.u64(e.hi);
    out.u64(e.lo);
    out.u32(e.contact);
    out.boolean(e.swapped);
    out.boolean(e.hit);
  }
}

void ContactEventTracker::load(ByteReader& in, bool keyedByIndex, const CollisionPipeline& collision) {
  touching_.resize(in.count(8 + 8 + 4 + 1 + 1, "touching pairs"));
  for (Entry& e : touching_) {
    e.hi = in.u64();
    e.lo = in.u64();
    e.contact = in.u32();
    e.swapped = in.boolean();
    e.hit = in.boolean();
  }
  // afterNarrowPhase merges against them in key order.
  if (!std::is_sorted(touching_.begin(), touching_.end())) in.fail("the touching pairs are not in key order");
  if (keyedByIndex) {
    for (Entry& e : touching_) {
      if ((e.hi & kPlaneBit) == 0) continue;
      const std::uint64_t index = e.lo >> 32;
      if (index >= collision.bodyCount()) in.fail("a touching pair naming a body past the " + std::to_string(collision.bodyCount()));
      e.lo = (std::uint64_t{collision.proxyOf(index)} << 32) | (e.lo & 0xffffffffull);
    }
    std::sort(touching_.begin(), touching_.end());
  }
  events_ = {};
  queuedEnds_.clear();
  asleep_.clear();
}

}  // namespace rbsim
