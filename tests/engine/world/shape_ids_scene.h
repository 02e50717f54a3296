#pragma once
// The scenes and checks shape_ids_test.cpp and shape_ids_snapshot_test.cpp share: static rows of
// boxes (compound bodies) and the shape table compared slot by slot.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "rbsim/body/compound_body.h"
#include "rbsim/world/shape_ids.h"
#include "rbsim/world/world.h"
#include "world/world_access.h"

namespace rbsim::test::shape_ids {

constexpr double kSpacing = 2.0;  // between a row's children [m]
constexpr double kHalf = 0.5;     // a child box's half extent [m]

// A row of `n` boxes on x, child k at x = kSpacing (k - (n - 1) / 2), their tops at y = 2 kHalf.
inline BodyDef row(int n, const std::string& name) {
  std::vector<CompoundPart> parts(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    parts[static_cast<std::size_t>(k)].shape = Shape::box(Vec3(kHalf, kHalf, kHalf));
    parts[static_cast<std::size_t>(k)].position = Vec3(kSpacing * (k - 0.5 * (n - 1)), 0.0, 0.0);
  }
  BodyDef def = compoundBodyDef(parts, name);
  def.position = Vec3(0.0, kHalf, 0.0);  // the parts' centre of mass, on the ground
  def.isStatic = true;
  return def;
}

inline World emptyWorld(double dt = 1.0 / 60.0) {
  Settings s;
  s.timeStep = dt;
  return World(s);
}

// Every live shape of the World by body index and child, as (slot, generation).
inline std::vector<ShapeId> allShapes(const World& w) {
  std::vector<ShapeId> out;
  for (std::size_t i = 0; i < w.bodies().size(); ++i) {
    for (const ShapeId id : shapeIds(w, w.idAt(i))) out.push_back(id);
  }
  return out;
}

inline void expectSameTable(const World& a, const World& b) {
  const ShapeTable& x = WorldAccess::shapeIds(a);
  const ShapeTable& y = WorldAccess::shapeIds(b);
  ASSERT_EQ(x.slots().size(), y.slots().size());
  for (std::size_t s = 0; s < x.slots().size(); ++s) {
    EXPECT_EQ(x.slots()[s].generation, y.slots()[s].generation) << "slot " << s;
    EXPECT_EQ(x.slots()[s].body, y.slots()[s].body) << "slot " << s;
    EXPECT_EQ(x.slots()[s].child, y.slots()[s].child) << "slot " << s;
    EXPECT_EQ(x.slots()[s].next, y.slots()[s].next) << "slot " << s;
  }
  EXPECT_EQ(x.freeSlot(), y.freeSlot());
}

}  // namespace rbsim::test::shape_ids
