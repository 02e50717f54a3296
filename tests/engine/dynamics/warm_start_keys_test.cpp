// Warm starts keyed by the bodies' stable keys (dynamics/contact_key.h pairKey; issue 58): a
// removal drops the removed bodies' entries and renames no other, and a snapshot from before
// version 6, whose entries name bodies by index, is renamed to the keys on load
// (dynamics/solver_snapshot.cpp renameToKeys).
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/contact_key.h"
#include "dynamics/soft_step_solver.h"
#include "math/byte_stream.h"
#include "rbsim/world/world.h"
#include "dynamics_util.h"

namespace rbsim {
namespace {

constexpr double kSettleTime = 1.0;  // [s] for the stack to rest: every pair touching, warm started

// A stack of three boxes on the ground, rested: the contacts and bodies of its last step.
World restedStack(double dt) {
  Settings s;
  s.timeStep = dt;
  s.allowSleep = false;
  World world(s);
  world.addPlane(Plane{});
  for (int k = 0; k < 3; ++k) {
    world.addBody(test::boxWith(Vec3::Constant(1.0), 1.0, Vec3(0.0, 0.5 + k, 0.0), Material{}, "box" + std::to_string(k)));
  }
  for (int i = 0; i < static_cast<int>(kSettleTime / dt); ++i) world.step();
  return world;
}

// The keys a soft step's saved warm starts hold, in order (solver_snapshot.cpp's layout: a count,
// then per entry its key, its point count, per point 24 + 8 + 24 + 1 bytes, and a flag).
std::vector<std::uint64_t> savedKeys(const SoftStepSolver& solver) {
  ByteWriter out;
  solver.save(out);
  ByteReader in(out.bytes().data(), out.bytes().size(), "solver");
  std::vector<std::uint64_t> keys(in.count(13, "cached manifolds"));
  for (std::uint64_t& key : keys) {
    key = in.u64();
    const std::uint32_t points = in.u32();
    for (std::uint32_t p = 0; p < points * (24 + 8 + 24 + 1); ++p) in.u8();
    in.boolean();
  }
  return keys;
}

// A solver that solved the stack's last contacts once, its bodies keyed by index.
SoftStepSolver solvedOnce(World& world, IdTable<BodyId>& ids) {
  for (std::size_t i = 0; i < world.bodies().size(); ++i) ids.add();
  std::vector<RigidBody> bodies = world.bodies();
  std::vector<Joint> joints;
  const std::vector<Material> materials(bodies.size()), planeMaterials(world.planes().size());
  SoftStepSolver solver;
  solver.solve({bodies, world.contacts(), joints, ids, materials, planeMaterials, world.settings()});
  return solver;
}

TEST(WarmStartKeys, AnOlderSnapshotsIndicesBecomeTheBodiesKeys) {
  for (const double dt : {1.0 / 60.0, 1.0 / 240.0}) {
    World world = restedStack(dt);
    IdTable<BodyId> ids;
    const SoftStepSolver solver = solvedOnce(world, ids);
    const std::vector<std::uint64_t> byIndex = savedKeys(solver);
    ASSERT_EQ(byIndex.size(), 3u) << "ground-box, box-box, box-box";
    ByteWriter out;
    solver.save(out);
    // The same bodies, their keys now 7, 3 and 5 (a World that removed and added bodies).
    const std::vector<std::uint32_t> keys{7, 3, 5};
    std::vector<std::uint64_t> expected;
    for (const std::uint64_t key : byIndex) {
      const bool plane = (key >> 63) != 0;
      const std::uint64_t a = (key >> 24) & 0xffffff, b = key & 0xffffff;
      expected.push_back((key & ~std::uint64_t{0xffffffffffff}) | ((plane ? a : keys[a]) << 24) | keys[b]);
    }
    std::sort(expected.begin(), expected.end());
    ByteReader in(out.bytes().data(), out.bytes().size(), "solver");
    SoftStepSolver renamed;
    renamed.load(in, keys, true);
    EXPECT_EQ(savedKeys(renamed), expected) << dt;
    // Read as keyed already, the same bytes name bodies 0, 1 and 2, none of which lives: refused.
    ByteReader again(out.bytes().data(), out.bytes().size(), "solver");
    SoftStepSolver refused;
    EXPECT_THROW(refused.load(again, keys, false), std::invalid_argument) << dt;
  }
}

TEST(WarmStartKeys, ARemovalDropsTheRemovedBodysEntriesAndRenamesNone) {
  World world = restedStack(1.0 / 60.0);
  IdTable<BodyId> ids;
  SoftStepSolver solver = solvedOnce(world, ids);
  const std::vector<std::uint64_t> before = savedKeys(solver);
  ASSERT_EQ(before.size(), 3u);
  // Key 1 (the middle box) goes: both its pairs' entries, and only those, leave, the rest as they were.
  solver.bodiesRemoved({1}, {});
  std::vector<std::uint64_t> expected;
  for (const std::uint64_t key : before) {
    if (!namesRemoved(key, {1})) expected.push_back(key);
  }
  EXPECT_EQ(expected.size(), 1u) << "the ground-box pair stays";
  EXPECT_EQ(savedKeys(solver), expected);
}

}  // namespace
}  // namespace rbsim
