#pragma once
// What writes and reads a World snapshot behind World's public surface (world/world_snapshot.h):
// World names it a friend. world_snapshot.cpp writes and reads the World's members,
// world_snapshot_bodies.cpp its bodies.
#include "math/byte_stream.h"
#include "rbsim/world/world.h"

namespace rbsim {

struct WorldSnapshotAccess {
  static void save(const World& world, ByteWriter& out);
  static World load(ByteReader& in, const World& base, std::uint32_t version);  // of the snapshot read
  // Each body's record: its constants' fingerprint, name, colour, material, kind, state, rotation,
  // sleep, accumulators and free-flow memo.
  static void saveBodies(const World& world, ByteWriter& out);
  // The bodies added to `world` (a World with none yet) in order, each from the constants of a
  // body, spawner prototype or fracture piece of `base` with its fingerprint.
  static void loadBodies(ByteReader& in, const World& base, World& world);
  // The shapes' id table, read (version 5 on) or made afresh (version 4), once the bodies' ids are.
  static void readShapeTable(ByteReader& in, std::uint32_t version, World& world);
};

}  // namespace rbsim
