#pragma once
// A binary snapshot of a World (issue 57): everything World::step reads, so that a World read
// from it, in this process or another, steps bit for bit as the saved one would (Jolt's
// PhysicsSystem::SaveState / RestoreState with StateRecorder, MuJoCo's mj_copyData).
//
// Saved: every body's state, its rotation matrix apart from q, awake flag, resting time, which
// earlier body's mesh object it shares (the renderer's instancing groups them by it, and uploads
// a mesh object once: a body read back keeps the base World's object of its id when equal),
// accumulated forces and the exact integrator's free-flow memo; the ids (slots, generations, the
// free list) and the shapes' ids; materials, planes, scripted forces, springs, joints with their warm starts, pose
// events, kinematic motions, spawners (their random streams and living bursts), the kill volume,
// the step count and time origin, the settings; the collision stages' proxies, boxes, contacts
// and recycling frames; the contact solver's warm starts and last contact points; the last
// step's fracture events and spawned and removed ids.
//
// Not saved, as Jolt's SaveState saves no shapes: the bodies' constant parts (meshes, shapes,
// grids, compound children, fracture patterns, spawner prototypes). A snapshot is read against a
// base World built from the same definitions (the same scene), whose bodies, spawner prototypes
// and fracture pieces supply them: each saved body names its constants by a fingerprint of them
// (shapeFingerprint). Refused, with a std::invalid_argument naming them: step listeners
// (particles, soft bodies, the 2D world), the LCP solver, a body matching nothing in the base.
//
// Format (version kWorldSnapshotVersion): the 8-byte magic "RBSIMWSN", a u32 version, a u64
// payload size, the payload, and the payload's FNV-1a 64 checksum; integers little-endian fixed
// width, doubles by their bit pattern (math/byte_stream.h). Reading checks the magic, version,
// size, checksum, then every count, index and id: a truncated or corrupted snapshot is a
// std::invalid_argument, never a crash or an allocation larger than the snapshot allows.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rbsim/world/world.h"

namespace rbsim {

// 2: which bodies share one mesh object (issue 58: a World read back is drawn in the same
// instanced batches). 3: a body record has no colour (issue 58: colours are the app's,
// rbsim/scene/view_desc.h). 4: the joints' and springs' id tables (issue 58: a JointId or SpringId
// taken before a save names the same joint or spring in the World read back). 5: the shapes' id
// table (issue 58, world/shape_ids.h). Version 4 still loads: its shape ids are made afresh, as
// adding its bodies in index order would make them (slots 0, 1, ... in child order, generation 0).
// 6: the warm starts name bodies by their id slots, not their indices (dynamics/contact_key.h
// pairKey); an older version's are renamed on load.
inline constexpr std::uint32_t kWorldSnapshotVersion = 6;
inline constexpr std::uint32_t kOldestWorldSnapshotVersion = 4;  // the oldest version read

// Throws std::invalid_argument for a World with a step listener or the LCP solver.
std::vector<std::uint8_t> saveWorldSnapshot(const World& world);

// A new World, as the saved one was, taking the bodies' constant parts from `base` (a World
// built from the same definitions, at any step: its bodies, spawners and fracture patterns are
// looked at, nothing of it changes). `what` names the snapshot in messages (a file, "snapshot").
// Throws std::invalid_argument.
World loadWorldSnapshot(const std::uint8_t* data, std::size_t size, const World& base,
                        const std::string& what = "snapshot");
inline World loadWorldSnapshot(const std::vector<std::uint8_t>& bytes, const World& base,
                               const std::string& what = "snapshot") {
  return loadWorldSnapshot(bytes.data(), bytes.size(), base, what);
}

// Checks what can be checked without a base World: the magic, version, size and checksum.
// Throws std::invalid_argument naming `what`.
void checkWorldSnapshot(const std::uint8_t* data, std::size_t size, const std::string& what);

// A hash of what a body has from its definition and keeps for life (mesh, shape, compound
// children, mass, inertia, file frame, kinds of grid): two bodies with equal fingerprints share
// their constant parts (up to a 64-bit hash collision).
std::uint64_t shapeFingerprint(const RigidBody& body, const BodySolid& solid);

}  // namespace rbsim
