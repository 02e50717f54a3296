#pragma once
// Ids of a generation for items kept in a dense array (the World's bodies, body/body_id.h, and its
// joints and springs, world/item_ids.h; Box2D v3's id pool with generation-checked ids): per slot the item's index in the array (or, for a free slot, the
// next free slot) and its generation; per item its slot. Removing an item moves its slot's
// generation on and puts the slot on the free list, so an id kept past the removal is stale even
// once the slot names a new item.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rbsim {

template <typename Id>
class IdTable {
 public:
  struct Slot {
    std::uint32_t index = 0;
    std::uint32_t generation = 0;
  };
  static constexpr std::uint32_t kNoSlot = UINT32_MAX;

  // The id of the item just appended to the array.
  Id add() {
    std::uint32_t slot = freeSlot_;
    if (slot == kNoSlot) {
      slot = static_cast<std::uint32_t>(slots_.size());
      slots_.push_back({});
    } else {
      freeSlot_ = slots_[slot].index;
    }
    slots_[slot].index = static_cast<std::uint32_t>(slotOfItem_.size());
    slotOfItem_.push_back(slot);
    return Id{slot, slots_[slot].generation};
  }

  bool isValid(Id id) const {
    return id.slot < slots_.size() && slots_[id.slot].generation == id.generation &&
           slots_[id.slot].index < slotOfItem_.size() && slotOfItem_[slots_[id.slot].index] == id.slot;
  }
  std::size_t indexOf(Id id) const { return slots_[id.slot].index; }  // of a valid id
  Id idAt(std::size_t index) const { return Id{slotOfItem_[index], slots_[slotOfItem_[index]].generation}; }
  std::size_t size() const { return slotOfItem_.size(); }

  // Erases from `items` (the array the ids name) those for which gone(item) is true, the others
  // keeping their order, and retires the erased items' ids. gone sees each item once, in order,
  // and may change the ones it keeps.
  template <typename T, typename Gone>
  void erase(std::vector<T>& items, Gone gone) {
    eraseRanked(items, [&](T& item) { return gone(item) ? std::size_t{0} : kKept; });
  }

  // As erase, rankOf(item) saying kKept or the erased item's rank: the slots join the free list
  // by rank, then in array order, as erasing rank 0's items, then rank 1's, ... one call each
  // would leave them (World::destroyBodies, a batch removed as one body after another).
  static constexpr std::size_t kKept = SIZE_MAX;
  template <typename T, typename RankOf>
  void eraseRanked(std::vector<T>& items, RankOf rankOf) {
    std::vector<std::pair<std::size_t, std::uint32_t>> freed;  // (rank, slot)
    std::size_t kept = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::uint32_t slot = slotOfItem_[i];
      const std::size_t rank = rankOf(items[i]);
      if (rank != kKept) {
        freed.emplace_back(rank, slot);
        continue;
      }
      // Not onto itself: a self-move leaves a std::string member empty (libstdc++).
      if (kept != i) items[kept] = std::move(items[i]);
      slotOfItem_[kept] = slot;
      slots_[slot].index = static_cast<std::uint32_t>(kept);
      ++kept;
    }
    items.resize(kept);
    slotOfItem_.resize(kept);
    std::stable_sort(freed.begin(), freed.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [rank, slot] : freed) {
      ++slots_[slot].generation;
      slots_[slot].index = freeSlot_;
      freeSlot_ = slot;
    }
  }

  // Retires a valid id whose item the caller swap-removes from its array (World::destroyBodies:
  // the last item takes the removed one's index): the slot's generation moves on and the slot
  // joins the free list; the last item keeps its slot, which now points at the returned index.
  // Returns the removed item's index; the last item's was size() after the call.
  std::uint32_t swapRemove(Id id) {
    const std::uint32_t removed = slots_[id.slot].index;
    const std::uint32_t last = static_cast<std::uint32_t>(slotOfItem_.size() - 1);
    ++slots_[id.slot].generation;
    slots_[id.slot].index = freeSlot_;
    freeSlot_ = id.slot;
    if (removed != last) {
      slotOfItem_[removed] = slotOfItem_[last];
      slots_[slotOfItem_[removed]].index = removed;
    }
    slotOfItem_.pop_back();
    return removed;
  }

  // Erases items[index] (later items move down one), retiring its id.
  template <typename T>
  void eraseAt(std::vector<T>& items, std::size_t index) {
    std::size_t i = 0;
    erase(items, [&](const T&) { return i++ == index; });
  }

  // For a snapshot (world/world_snapshot.cpp): the table as it is, and set back from its parts
  // after checking them: every item's slot points back at it, and the free list runs through the
  // other slots exactly once. Returns what is wrong ("" when nothing is; the table is then set).
  const std::vector<Slot>& slots() const { return slots_; }
  const std::vector<std::uint32_t>& slotOfItem() const { return slotOfItem_; }
  std::uint32_t freeSlot() const { return freeSlot_; }
  std::string assign(std::vector<Slot> slots, std::vector<std::uint32_t> slotOfItem, std::uint32_t freeSlot) {
    std::vector<char> used(slots.size(), 0);
    for (std::size_t i = 0; i < slotOfItem.size(); ++i) {
      const std::uint32_t s = slotOfItem[i];
      if (s >= slots.size() || used[s] || slots[s].index != i) {
        return "item " + std::to_string(i) + "'s id slot " + std::to_string(s) + " does not name it";
      }
      used[s] = 1;
    }
    std::size_t freeCount = 0;
    for (std::uint32_t s = freeSlot; s != kNoSlot; s = slots[s].index) {
      if (s >= slots.size() || used[s]) return "the free list of id slots reaches slot " + std::to_string(s);
      used[s] = 1;
      ++freeCount;
    }
    if (slotOfItem.size() + freeCount != slots.size()) return "id slots neither an item's nor free";
    slots_ = std::move(slots);
    slotOfItem_ = std::move(slotOfItem);
    freeSlot_ = freeSlot;
    return "";
  }

 private:
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> slotOfItem_;
  std::uint32_t freeSlot_ = kNoSlot;  // head of the free list
};

}  // namespace rbsim
