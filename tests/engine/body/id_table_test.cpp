// The ids' table (body/id_table.h) under swap-removal, as World keeps its bodies' ids: against a
// dense array that moves its last item into each hole, every id ever issued is checked after
// every add and removal (the live ones name their item's index, the retired ones are stale), and
// freed slots come back last freed first, one generation on (Box2D v3's id pool).
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rbsim/body/body_id.h"
#include "rbsim/body/id_table.h"

namespace rbsim {
namespace {

TEST(BodyIdTable, SwapRemoveKeepsEveryIdNamingItsItemInADenseArray) {
  IdTable<BodyId> table;
  std::vector<int> items;        // the dense array: each item its serial number
  std::vector<BodyId> issued;    // by serial: the id add() gave
  std::vector<char> live;        // by serial
  std::mt19937 random(58);
  constexpr int kOperations = 4000;
  for (int op = 0; op < kOperations; ++op) {
    // Adds a little more often than it removes, so the table grows and its slots are reused.
    if (items.empty() || random() % 5 < 3) {
      const BodyId id = table.add();
      items.push_back(static_cast<int>(issued.size()));
      issued.push_back(id);
      live.push_back(1);
    } else {
      const std::size_t k = random() % items.size();
      const BodyId id = table.idAt(k);
      ASSERT_TRUE(id == issued[static_cast<std::size_t>(items[k])]);
      EXPECT_EQ(table.swapRemove(id), k);
      live[static_cast<std::size_t>(items[k])] = 0;
      items[k] = items.back();
      items.pop_back();
      ASSERT_EQ(table.size(), items.size());
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
      const BodyId id = issued[static_cast<std::size_t>(items[i])];
      ASSERT_TRUE(table.isValid(id)) << "operation " << op << ", item " << i;
      ASSERT_EQ(table.indexOf(id), i);
      ASSERT_TRUE(table.idAt(i) == id);
    }
    for (std::size_t s = 0; s < issued.size(); ++s) {
      if (!live[s]) ASSERT_FALSE(table.isValid(issued[s])) << "operation " << op << ", retired id " << s;
    }
  }
  // What a snapshot saves of it is accepted back as it is.
  IdTable<BodyId> copy;
  EXPECT_EQ(copy.assign(table.slots(), table.slotOfItem(), table.freeSlot()), "");
  for (std::size_t i = 0; i < items.size(); ++i) EXPECT_TRUE(copy.idAt(i) == table.idAt(i));
}

TEST(BodyIdTable, SwapRemoveFreesSlotsLastFirstOneGenerationOn) {
  IdTable<BodyId> table;
  const BodyId a = table.add(), b = table.add(), c = table.add(), d = table.add();
  // Removing b moves d (the last) into index 1; then a: c (now last) moves into index 0.
  EXPECT_EQ(table.swapRemove(b), 1u);
  EXPECT_EQ(table.indexOf(d), 1u);
  EXPECT_EQ(table.swapRemove(a), 0u);
  EXPECT_EQ(table.indexOf(c), 0u);
  EXPECT_EQ(table.indexOf(d), 1u);
  EXPECT_FALSE(table.isValid(a));
  EXPECT_FALSE(table.isValid(b));
  const BodyId first = table.add(), second = table.add();
  EXPECT_EQ(first.slot, a.slot);  // the last freed
  EXPECT_EQ(first.generation, a.generation + 1);
  EXPECT_EQ(second.slot, b.slot);
  EXPECT_EQ(second.generation, b.generation + 1);
  EXPECT_EQ(table.indexOf(first), 2u);  // appended
  EXPECT_EQ(table.indexOf(second), 3u);
  EXPECT_FALSE(table.isValid(a));  // a stale id stays stale once its slot holds another item
  // Removing the last item moves nothing.
  EXPECT_EQ(table.swapRemove(second), 3u);
  EXPECT_EQ(table.size(), 3u);
  EXPECT_EQ(table.indexOf(first), 2u);
}

}  // namespace
}  // namespace rbsim
