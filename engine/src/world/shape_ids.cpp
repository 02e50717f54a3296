// A World's shapes by id (world/shape_ids.h), read from its shape table (world/shape_table.h).
#include "rbsim/world/shape_ids.h"

#include <stdexcept>
#include <string>

#include "world/world_access.h"

namespace rbsim {

namespace {

const ShapeTable::Slot& checked(const World& world, ShapeId shape, const char* call) {
  if (!isValid(world, shape)) {
    throw std::invalid_argument(std::string(call) + ": shape id (slot " + std::to_string(shape.slot) + ", generation " +
                                std::to_string(shape.generation) +
                                ") is stale: its body was destroyed or broke, or it was never made here");
  }
  return WorldAccess::shapeIds(world).slot(shape);
}

// The body's index in World::bodies(), or std::invalid_argument naming the call.
std::size_t checkedBody(const World& world, BodyId body, const char* call) {
  if (!world.isValid(body)) {
    throw std::invalid_argument(std::string(call) + ": body id (slot " + std::to_string(body.slot) + ", generation " +
                                std::to_string(body.generation) + ") names no body: destroyed, or never made here");
  }
  return world.indexOf(body);
}

}  // namespace

bool isValid(const World& world, ShapeId shape) { return WorldAccess::shapeIds(world).isValid(shape); }

BodyId bodyOf(const World& world, ShapeId shape) {
  return WorldAccess::bodyIdOfSlot(world, checked(world, shape, "bodyOf").body);
}

std::size_t childOf(const World& world, ShapeId shape) { return checked(world, shape, "childOf").child; }

ShapeId shapeIdAt(const World& world, BodyId body, std::size_t child) {
  const std::size_t index = checkedBody(world, body, "shapeIdAt");
  const std::size_t count = shapeCountOf(world.bodies()[index]);
  if (child >= count) {
    throw std::invalid_argument("shapeIdAt: child " + std::to_string(child) + " of body '" + world.bodies()[index].name() +
                                "', which has " + std::to_string(count) + " shapes (expected 0 to " +
                                std::to_string(count - 1) + ")");
  }
  return WorldAccess::shapeIdOf(world, index, child);
}

std::vector<ShapeId> shapeIds(const World& world, BodyId body) {
  const std::size_t index = checkedBody(world, body, "shapeIds");
  const std::size_t count = shapeCountOf(world.bodies()[index]);
  std::vector<ShapeId> ids;
  ids.reserve(count);
  ShapeId id = WorldAccess::shapeIdOf(world, index, 0);
  for (std::size_t child = 0; child < count; ++child) {
    ids.push_back(id);
    const std::uint32_t next = WorldAccess::shapeIds(world).slot(id).next;
    if (next != ShapeTable::kNone) id = ShapeId{next, WorldAccess::shapeIds(world).slots()[next].generation};
  }
  return ids;
}

}  // namespace rbsim
