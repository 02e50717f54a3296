// The ids of a World's shapes (world/shape_table.h; Box2D v3's src/shape.c keeps them the same way).
#include "rbsim/world/shape_table.h"

#include <utility>

namespace rbsim {

void ShapeTable::add(std::uint32_t bodySlot, std::size_t count) {
  if (bodySlot >= firstOfBody_.size()) firstOfBody_.resize(bodySlot + std::size_t{1}, kNone);
  std::uint32_t previous = kNone;  // by index: a slot pushed back may move the others
  for (std::size_t child = 0; child < count; ++child) {
    std::uint32_t s = freeSlot_;
    if (s == kNone) {
      s = static_cast<std::uint32_t>(slots_.size());
      slots_.push_back({});
    } else {
      freeSlot_ = slots_[s].next;
    }
    Slot& slot = slots_[s];
    slot.body = bodySlot;
    slot.child = static_cast<std::uint32_t>(child);
    slot.next = kNone;
    (previous == kNone ? firstOfBody_[bodySlot] : slots_[previous].next) = s;
    previous = s;
  }
}

void ShapeTable::retire(std::uint32_t bodySlot) {
  std::uint32_t s = firstOfBody_[bodySlot];
  firstOfBody_[bodySlot] = kNone;
  while (s != kNone) {
    Slot& slot = slots_[s];
    const std::uint32_t next = slot.next;
    ++slot.generation;
    slot.body = kNone;
    slot.child = 0;
    slot.next = freeSlot_;
    freeSlot_ = s;
    s = next;
  }
}

ShapeId ShapeTable::idOf(std::uint32_t bodySlot, std::size_t child) const {
  std::uint32_t s = firstOfBody_[bodySlot];
  for (std::size_t k = 0; k < child; ++k) s = slots_[s].next;
  return ShapeId{s, slots_[s].generation};
}

std::string ShapeTable::assign(std::vector<Slot> slots, std::uint32_t freeSlot, const std::vector<std::size_t>& shapeCounts) {
  // Each body's child 0, from one pass; walking its links from there must meet children 1, 2, ...
  std::vector<std::uint32_t> first(shapeCounts.size(), kNone);
  for (std::uint32_t s = 0; s < slots.size(); ++s) {
    if (slots[s].body < first.size() && slots[s].child == 0 && first[slots[s].body] == kNone) first[slots[s].body] = s;
  }
  std::vector<char> used(slots.size(), 0);
  std::size_t live = 0;
  for (std::uint32_t b = 0; b < shapeCounts.size(); ++b) {
    if (shapeCounts[b] == 0) {
      first[b] = kNone;
      continue;
    }
    std::uint32_t s = first[b];
    for (std::size_t child = 0; child < shapeCounts[b]; ++child) {
      if (s >= slots.size() || used[s] || slots[s].body != b || slots[s].child != child) {
        return "body id slot " + std::to_string(b) + "'s shape " + std::to_string(child) + " is not where its list leads";
      }
      used[s] = 1;
      ++live;
      s = slots[s].next;
    }
    if (s != kNone) return "body id slot " + std::to_string(b) + " has more shapes than children";
  }
  std::size_t freeCount = 0;
  for (std::uint32_t s = freeSlot; s != kNone; s = slots[s].next) {
    if (s >= slots.size() || used[s] || slots[s].body != kNone) return "the free list of shape id slots reaches slot " + std::to_string(s);
    used[s] = 1;
    ++freeCount;
  }
  if (live + freeCount != slots.size()) return "shape id slots neither a body's nor free";
  slots_ = std::move(slots);
  firstOfBody_ = std::move(first);
  freeSlot_ = freeSlot;
  return "";
}

}  // namespace rbsim
