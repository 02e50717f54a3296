#pragma once
// Removing a batch of bodies (World::destroyBodies) as destroying them one at a time would, in one
// pass over what names bodies by index. destroyBody swap-removes: the last body moves into the
// removed one's index. A batch is that sequence of swap-removals, recorded once (O(k) for k
// bodies) as events per body; each array indexed by body is then gathered once, and each item
// naming bodies (a contact, a warm start) replays only the events of its own bodies. Removing 1e5
// resting boxes one at a time walked every contact and warm start for each (about 150 s). The
// record holds only the bodies the batch reached (sorted, looked up by binary search), so
// building it costs O(k log k) whatever the World's size (issue 58: removal costs what it touches).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace rbsim {

class BodyRemoval {
 public:
  static constexpr std::uint32_t kGone = UINT32_MAX;  // newIndex of a removed body

  // One swap-removal of the sequence: body index `removed` went and the last body, `last`, took
  // its index (removed == last: nothing moved). Indices as they were at that step.
  struct Step {
    std::uint32_t removed = 0, last = 0;
  };
  // What happened to a body at step `step`: it moved to index `to`, or (to == kGone) it went.
  struct Event {
    std::uint32_t step = 0, to = 0;
  };

  // `steps` as destroyBody would take them, one id after another, on `before` bodies.
  BodyRemoval(std::size_t before, std::vector<Step> steps);

  std::size_t before() const { return before_; }
  std::size_t after() const { return before_ - steps_.size(); }
  const std::vector<Step>& steps() const { return steps_; }
  // By index before the batch: the index after it, or kGone.
  std::uint32_t newIndex(std::size_t index) const {
    const Involved* at = find(index);
    return at ? at->newIndex : static_cast<std::uint32_t>(index);
  }
  // The removed bodies' indices before the batch, in the order removed.
  const std::vector<std::uint32_t>& removed() const { return removed_; }
  // By index before the batch: the body moved or went at some step.
  bool involves(std::size_t index) const { return find(index) != nullptr; }
  // The bodies the batch reached (removed or moved), by index before the batch, in order.
  std::size_t involvedCount() const { return involved_.size(); }
  std::uint32_t involvedBody(std::size_t k) const { return involved_[k].body; }
  // Per index after the batch that holds another body than before: (new index, old index). Only
  // such indices change; the old ones are all past after(), so gathering cannot overwrite a source.
  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& moves() const { return moves_; }
  // Per index before the batch: what happened to the body, in step order.
  // Both null for a body the batch did not reach.
  const Event* eventsBegin(std::size_t index) const;
  const Event* eventsEnd(std::size_t index) const;

  // An array indexed by body, brought to the bodies after the batch.
  template <typename T>
  void gather(std::vector<T>& items) const {
    for (const auto& [to, from] : moves_) items[to] = std::move(items[from]);
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(after()), items.end());
  }

  // Replays the sequence on an item naming body indices `a` and `b` (before the batch; `pair`
  // false: `a` is not a body's, as a plane's index, and only `b` moves), as destroyBody's
  // renumbering would step by step: false when the item goes with a removed body (`gone(partner)`
  // is told the other body's index before the batch, when it names one), or when a pair in order
  // (the lower index first) turns round and `turn(moved, partner)` (indices before the batch)
  // refuses; a pair that turns has its a and b swapped. On true, a and b are the indices after.
  template <class Turn, class Gone>
  bool replay(bool pair, std::size_t& a, std::size_t& b, Turn&& turn, Gone&& gone) const {
    std::size_t bodyA = a, bodyB = b;  // indices before the batch of what a and b name now
    const Event *ia = pair ? eventsBegin(a) : nullptr, *ea = pair ? eventsEnd(a) : nullptr;
    const Event *ib = eventsBegin(b), *eb = eventsEnd(b);
    while (ia != ea || ib != eb) {
      // At one step a body may go and its partner move into its index: the removal comes first.
      const bool onA = ib == eb || (ia != ea && (ia->step < ib->step || (ia->step == ib->step && ia->to == kGone)));
      const Event& e = onA ? *ia++ : *ib++;
      if (e.to == kGone) {
        if (pair) gone(onA ? bodyB : bodyA);
        return false;
      }
      const bool inOrder = a < b;
      (onA ? a : b) = e.to;
      if (pair && inOrder && a > b) {
        if (!turn(onA ? bodyA : bodyB, onA ? bodyB : bodyA)) return false;
        std::swap(a, b);
        std::swap(bodyA, bodyB);
        std::swap(ia, ib);
        std::swap(ea, eb);
      }
    }
    return true;
  }

 private:
  struct Involved {
    std::uint32_t body = 0;        // index before the batch
    std::uint32_t firstEvent = 0;  // into events_; its events run to the next body's first
    std::uint32_t newIndex = 0;    // index after the batch, or kGone
  };
  const Involved* find(std::size_t index) const;  // null: the batch did not reach the body

  std::size_t before_;
  std::vector<Step> steps_;
  std::vector<std::uint32_t> removed_;
  std::vector<Involved> involved_;  // sorted by body
  std::vector<Event> events_;       // grouped by body, as involved_, each body's in step order
  std::vector<std::pair<std::uint32_t, std::uint32_t>> moves_;
};

}  // namespace rbsim
