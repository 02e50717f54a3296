#pragma once
// Removing a batch of bodies (World::destroyBodies) as destroying them one at a time would, in one
// pass over what names bodies by index. destroyBody swap-removes: the last body moves into the
// removed one's index. A batch is that sequence of swap-removals, recorded once (O(k) for k
// bodies) as where each body it reached ends; each array indexed by body is then gathered once,
// and each item naming bodies by index (a contact) looks up only its own bodies. Removing 1e5
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
  // An array indexed by body, brought to the bodies after the batch.
  template <typename T>
  void gather(std::vector<T>& items) const {
    for (const auto& [to, from] : moves_) items[to] = std::move(items[from]);
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(after()), items.end());
  }

 private:
  struct Involved {
    std::uint32_t body = 0;      // index before the batch
    std::uint32_t newIndex = 0;  // index after the batch, or kGone
  };
  const Involved* find(std::size_t index) const;  // null: the batch did not reach the body

  std::size_t before_;
  std::vector<Step> steps_;
  std::vector<std::uint32_t> removed_;
  std::vector<Involved> involved_;  // sorted by body
  std::vector<std::pair<std::uint32_t, std::uint32_t>> moves_;
};

}  // namespace rbsim
