// The World's body table (rbsim/world/body_table.h): its one add and its one removal.
#include "rbsim/world/body_table.h"

#include <type_traits>

#include "body/body_removal.h"
#include "rbsim/fracture/fracture.h"

namespace rbsim {

template <typename Fn>
void BodyTable::forEachColumn(Fn&& fn) {
  fn(bodies);
  fn(materials);
  fn(solids);
  fn(fracturePatterns);
  fn(listed);
  fn(proxies);
  fn(radius);
  fn(thickness);
  fn(reach);
  fn(start);
  fn(fast);
  fn(hasGrid);
  fn(meshGround);
  fn(gap);
  fn(boxes);
  fn(keptContacts);
}

// The 16 columns forEachColumn visits, then the ids and the shapes' ids. If this fails, a column
// was added to or removed from BodyTable: list it in forEachColumn, then set the count here.
// Checked where the standard library lays out vectors in 3 pointers of 8 bytes (as World's copy,
// docs/ci.md).
constexpr std::size_t kColumns = 16;
static_assert(sizeof(void*) != 8 || sizeof(std::vector<char>) != 24 ||
                  sizeof(BodyTable) == kColumns * sizeof(std::vector<char>) + sizeof(IdTable<BodyId>) + sizeof(ShapeTable),
              "a column was added to or removed from BodyTable: list it in forEachColumn (body_table.cpp)");

BodyId BodyTable::add(const BodyDef& def) {
  // The body first (it throws on an invalid def, before any column grows), then a default row in
  // every other column, then the World's own values in its columns.
  bodies.emplace_back(def);
  forEachColumn([](auto& column) {
    if constexpr (!std::is_same_v<std::decay_t<decltype(column)>, std::vector<RigidBody>>) column.emplace_back();
  });
  materials.back() = def.material;
  solids.back() = bodySolidOf(def);
  fracturePatterns.back() = def.fracture;
  const BodyId id = ids.add();
  shapeIds.add(id.slot, shapeCountOf(bodies.back()));  // its shapes' ids, in child order
  return id;
}

BodyRemoval BodyTable::retire(const std::vector<BodyId>& removed) {
  std::vector<BodyRemoval::Step> steps;
  steps.reserve(removed.size());
  for (const BodyId id : removed) {
    const std::uint32_t row = ids.swapRemove(id);
    steps.push_back({row, static_cast<std::uint32_t>(ids.size())});
  }
  // Body after body, as one destroyBody after another retires them.
  for (const BodyId id : removed) shapeIds.retire(id.slot);
  return BodyRemoval(bodies.size(), std::move(steps));
}

void BodyTable::gather(const BodyRemoval& removal) {
  forEachColumn([&](auto& column) { removal.gather(column); });
}

}  // namespace rbsim
