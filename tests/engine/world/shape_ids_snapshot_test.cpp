// Shape ids in a World snapshot (world/world_snapshot.h, version 5; issue 58): a World read back
// keeps the shape table; a version 4 snapshot (no table) makes it as adding its bodies in order
// does; a table whose links are broken is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rbsim/body/shape_body.h"
#include "rbsim/world/shape_ids.h"
#include "rbsim/world/world.h"
#include "rbsim/world/world_snapshot.h"
#include "refusal.h"
#include "shape_ids_scene.h"
#include "test_util.h"
#include "world/world_access.h"

namespace rbsim::test::shape_ids {
namespace {

// The scene of the snapshot tests: a box, rows of 2 and 3, a ball; then the row of 2 destroyed,
// so that the table has freed slots and generations past 0.
World snapshotScene() {
  World w = emptyWorld();
  w.addBody(boxDef(Vec3(1, 1, 1), 1.0, "box"));
  const BodyId two = w.addBody(row(2, "two"));
  w.addBody(row(3, "three"));
  w.addBody(shapeBodyDef(Shape::sphere(0.5), 1.0, "ball"));
  w.destroyBody(two);
  return w;
}

// FNV-1a 64, the snapshot's checksum (world_snapshot.cpp), to write a version 4 file.
std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

TEST(ShapeIdsSnapshot, AWorldReadBackKeepsItsShapeIds) {
  const World w = snapshotScene();
  const World base = snapshotScene();
  World back = loadWorldSnapshot(saveWorldSnapshot(w), base);
  expectSameTable(back, w);
  EXPECT_EQ(allShapes(back), allShapes(w));
  World live(w);
  EXPECT_EQ(shapeIds(back, back.addBody(row(3, "new"))), shapeIds(live, live.addBody(row(3, "new"))));
}

// The same bytes without the shape table, marked version 4: the table read back is the one
// adding the bodies in index order makes (slots 0, 1, ... generation 0); a table whose link is
// broken is refused by name.
TEST(ShapeIdsSnapshot, AVersion4SnapshotMakesTheShapeIdsAfresh) {
  const World w = snapshotScene();
  std::vector<std::uint8_t> bytes = saveWorldSnapshot(w);
  // The table as saved: u64 slot count, per slot generation, body, child, next (u32), u32 free head.
  std::vector<std::uint8_t> table;
  const auto put = [&](std::uint64_t v, int width) {
    for (int k = 0; k < width; ++k) table.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  };
  const ShapeTable& shapes = WorldAccess::shapeIds(w);
  put(shapes.slots().size(), 8);
  for (const ShapeTable::Slot& s : shapes.slots()) {
    put(s.generation, 4);
    put(s.body, 4);
    put(s.child, 4);
    put(s.next, 4);
  }
  put(shapes.freeSlot(), 4);
  const auto at = std::search(bytes.begin(), bytes.end(), table.begin(), table.end());
  ASSERT_NE(at, bytes.end());
  constexpr std::size_t kHeader = 8 + 4 + 8, kChecksum = 8;
  const auto reseal = [&](std::vector<std::uint8_t>& b, std::uint32_t version) {
    const std::uint64_t payload = b.size() - kHeader - kChecksum;
    for (int k = 0; k < 4; ++k) b[8 + k] = static_cast<std::uint8_t>(version >> (8 * k));
    for (int k = 0; k < 8; ++k) b[12 + k] = static_cast<std::uint8_t>(payload >> (8 * k));
    const std::uint64_t sum = fnv1a(b.data() + kHeader, payload);
    for (int k = 0; k < 8; ++k) b[kHeader + payload + k] = static_cast<std::uint8_t>(sum >> (8 * k));
  };
  std::vector<std::uint8_t> broken = bytes;
  const std::size_t offset = static_cast<std::size_t>(at - bytes.begin());
  broken[offset + 8 + 8] ^= 1;  // slot 0 (the box's one shape) says child 1
  reseal(broken, kWorldSnapshotVersion);
  const World base = snapshotScene();
  expectRefused([&] { loadWorldSnapshot(broken, base); }, "shape ids: ");
  bytes.erase(at, at + static_cast<std::ptrdiff_t>(table.size()));
  reseal(bytes, 4);
  const World back = loadWorldSnapshot(bytes, base);
  std::uint32_t slot = 0;
  for (std::size_t i = 0; i < back.bodies().size(); ++i) {
    EXPECT_EQ(back.idAt(i), w.idAt(i));
    for (const ShapeId id : shapeIds(back, back.idAt(i))) EXPECT_EQ(id, (ShapeId{slot++, 0}));
  }
  EXPECT_EQ(WorldAccess::shapeIds(back).slots().size(), slot);
}

}  // namespace
}  // namespace rbsim::test::shape_ids
