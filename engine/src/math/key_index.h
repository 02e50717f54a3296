#pragma once
// A table from nonzero 64-bit keys to 32-bit indices, rebuilt every step: open addressing with
// linear probing at most half full, Fibonacci hashing (Knuth, TAOCP vol. 3, 6.4). The collision
// pipeline finds last step's recycling frame of a pair with it, and the soft step a manifold's
// warm start: one probe into a table of 16-byte entries, where a binary search over sorted
// 400-byte frames took 14 cache misses, and sorting them took 4 % of a pyramid's step.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "math/byte_stream.h"

namespace rbsim {

class KeyIndex {
 public:
  // Empties the table and sizes it for up to `count` keys.
  void reset(std::size_t count) {
    std::size_t capacity = 16;
    shift_ = 60;
    while (capacity < 2 * count) {
      capacity *= 2;
      --shift_;
    }
    slots_.assign(capacity, Slot{});
  }
  void clear() { slots_.clear(); }
  // The largest index a key maps to, or -1 when no key is held (a table reset for a step that
  // kept nothing has slots and no key), for checking a loaded table against what it indexes.
  std::int64_t maxIndex() const {
    std::int64_t m = -1;
    for (const Slot& s : slots_) m = s.key != 0 && static_cast<std::int64_t>(s.index) > m ? s.index : m;
    return m;
  }
  bool empty() const { return slots_.empty(); }
  // Maps `key` (nonzero; 0 marks an empty slot) to `index`; a key given twice keeps the first.
  // At most the `count` of the last reset: the table is then half full, and a probe ends.
  void insert(std::uint64_t key, std::uint32_t index) {
    for (std::size_t s = home(key);; s = (s + 1) & (slots_.size() - 1)) {
      if (slots_[s].key == key) return;
      if (slots_[s].key == 0) {
        slots_[s] = {key, index};
        return;
      }
    }
  }
  std::optional<std::uint32_t> find(std::uint64_t key) const {
    if (slots_.empty()) return std::nullopt;
    for (std::size_t s = home(key);; s = (s + 1) & (slots_.size() - 1)) {
      if (slots_[s].key == key) return slots_[s].index;
      if (slots_[s].key == 0) return std::nullopt;
    }
  }
  // A World snapshot (world/world_snapshot.h): the table as it is, probe order and all, since
  // insert keeps the first of equal keys and a rebuild would need the order they came in.
  void save(ByteWriter& out) const {
    out.u32(static_cast<std::uint32_t>(shift_));
    out.count(slots_.size());
    for (const Slot& s : slots_) {
      out.u64(s.key);
      out.u32(s.index);
    }
  }
  void load(ByteReader& in) {
    const std::uint32_t shift = in.u32();
    const std::size_t count = in.count(12, "key index slots");
    // Empty, or a power of two >= 16 matching the shift (reset's table).
    const bool empty = count == 0;
    const bool power = count >= 16 && (count & (count - 1)) == 0 && shift < 64 && (std::size_t{1} << (64 - shift)) == count;
    if (!empty && !power) in.fail("a key index of " + std::to_string(count) + " slots with shift " + std::to_string(shift));
    std::vector<Slot> slots(count);
    for (Slot& s : slots) {
      s.key = in.u64();
      s.index = in.u32();
    }
    // A probe stops at an empty slot: a full table would loop forever.
    bool hasEmpty = empty;
    for (const Slot& s : slots) hasEmpty = hasEmpty || s.key == 0;
    if (!hasEmpty) in.fail("a key index without an empty slot");
    slots_ = std::move(slots);
    shift_ = static_cast<int>(shift);
  }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t index = 0;
  };
  // 2^64 / phi, odd: Fibonacci hashing spreads consecutive keys over the table's top bits.
  static constexpr std::uint64_t kGoldenMultiplier = 0x9E3779B97F4A7C15ull;
  std::size_t home(std::uint64_t key) const { return static_cast<std::size_t>((key * kGoldenMultiplier) >> shift_); }

  std::vector<Slot> slots_;
  int shift_ = 60;  // 64 - log2(capacity)
};

}  // namespace rbsim
