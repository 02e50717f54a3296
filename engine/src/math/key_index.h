#pragma once
// A table from nonzero 64-bit keys to 32-bit indices, rebuilt every step: open addressing with
// linear probing at most half full, Fibonacci hashing (Knuth, TAOCP vol. 3, 6.4). The collision
// pipeline finds last step's recycling frame of a pair with it, and the soft step a manifold's
// warm start: one probe into a table of 16-byte entries, where a binary search over sorted
// 400-byte frames took 14 cache misses, and sorting them took 4 % of a pyramid's step.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

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
