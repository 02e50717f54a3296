// math/key_index.h: every key found at its index, every absent key not found, against std::map,
// with tables up to their fill limit (half full), so that probes run past taken slots.
#include "math/key_index.h"

#include <cstdint>
#include <map>
#include <random>

#include <gtest/gtest.h>

namespace rbsim {
namespace {

TEST(KeyIndex, FindsWhatAMapFindsUpToItsFillLimit) {
  std::mt19937_64 random(54);
  for (std::size_t count : {1u, 7u, 100u, 5000u}) {
    KeyIndex index;
    index.reset(count);
    std::map<std::uint64_t, std::uint32_t> expected;
    for (std::size_t i = 0; i < count; ++i) {
      // Regular keys (the pipeline's are body indices shifted by 32) and random ones.
      const std::uint64_t key = i % 2 == 0 ? (std::uint64_t{i} + 1) << 40 : (random() | 1u);
      const auto value = static_cast<std::uint32_t>(i);
      index.insert(key, value);
      expected.emplace(key, value);  // a key given twice keeps the first, as the index does
    }
    for (const auto& [key, value] : expected) {
      ASSERT_TRUE(index.find(key).has_value()) << count;
      EXPECT_EQ(*index.find(key), value) << count;
    }
    for (int k = 0; k < 1000; ++k) {
      const std::uint64_t key = random() | 1u;
      EXPECT_EQ(index.find(key).has_value(), expected.count(key) == 1) << count;
    }
  }
}

TEST(KeyIndex, ResetAndClearForgetEveryKey) {
  KeyIndex index;
  EXPECT_FALSE(index.find(1).has_value());  // never filled
  index.reset(4);
  index.insert(3, 9);
  index.insert(3, 10);
  EXPECT_EQ(index.find(3), std::optional<std::uint32_t>(9));
  index.reset(4);
  EXPECT_FALSE(index.find(3).has_value());
  index.insert(5, 1);
  index.clear();
  EXPECT_FALSE(index.find(5).has_value());
}

// What a World snapshot's reader checks a loaded table against (collision_pipeline_snapshot.cpp):
// a table reset for a step that kept no frame holds slots and no key, and names no index, so a
// valid snapshot of it must not be refused as naming frame 0 of none (seen under clang's -O1).
TEST(KeyIndex, MaxIndexIsMinusOneWithoutAKeyAndTheLargestWithKeys) {
  KeyIndex index;
  EXPECT_EQ(index.maxIndex(), -1);  // no slots
  index.reset(4);
  EXPECT_FALSE(index.empty());
  EXPECT_EQ(index.maxIndex(), -1);  // slots, no key
  index.insert(7, 0);
  EXPECT_EQ(index.maxIndex(), 0);
  index.insert(9, 3);
  index.insert(11, 2);
  EXPECT_EQ(index.maxIndex(), 3);
}

}  // namespace
}  // namespace rbsim
