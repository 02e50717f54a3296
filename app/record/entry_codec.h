#pragma once
// One entry of a recording (record/recording.h): a world after one step, as bytes and back.
//
//   u16 world, with kBodySetFlag set when the step changed the World's set of bodies (spawned,
//       removed by the kill volume or a lifetime, broken into pieces); then u64 n and n bytes of a
//       World snapshot (rbsim/world/world_snapshot.h) taken after the step, which a replay loads
//       against the scene's World to have the same bodies, ids and order. A step that changes no
//       body costs no byte more than before.
//   u64 step; u32 bodies and per body x, q (w x y z), P, L as doubles and a flags byte (bit 0:
//       awake; bit 1, kOwnRotation: R's 9 doubles follow, column by column, for a body whose R
//       is not q's matrix bit for bit: euler-matrix without drift correction, a solver's nearest
//       rotation), in the World's order (the snapshot of the last change fixes it, with the
//       ids); u32 particle
//       systems and per system its live particles' attributes; u32 soft bodies and per body its
//       nodes' x and v; u32 2D bodies and per body x, theta, P, L (planar/planar_body.h).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rbsim/world/world.h"

namespace rbsim::app {

inline constexpr std::uint16_t kBodySetFlag = 0x8000;  // in the world field: a snapshot follows
inline constexpr std::uint8_t kAwake = 1, kOwnRotation = 2;  // a body's flags byte

// Appends world `world`'s entry; `bodySet` non-null: the World snapshot the entry carries.
void appendEntry(std::vector<std::uint8_t>& out, std::size_t world, const World& state,
                 const std::vector<std::uint8_t>* bodySet);

// Called with a problem; must throw (the reader's InputError naming the file).
using EntryFail = std::function<void(const std::string&)>;

// The bytes of the entry at data[0..size): fail when it runs past them.
std::size_t entryLength(const std::uint8_t* data, std::size_t size, const EntryFail& fail);

// The parts of an entry: its world index (flag cleared), whether it carries a snapshot, the
// snapshot's bytes, and where the step's state begins. fail when they run past the entry.
struct EntryParts {
  std::uint16_t world = 0;
  const std::uint8_t* snapshot = nullptr;
  std::size_t snapshotBytes = 0;
  std::size_t stateOffset = 0;  // of the u64 step
};
EntryParts entryParts(const std::vector<std::uint8_t>& entry, const EntryFail& fail);

// The entry's state, from parts.stateOffset, into `world`, which must hold its bodies, particle
// systems, soft bodies and 2D bodies (checked; fail names entry `number`). With nextStep, the
// step must be the one after the world's.
void restoreState(const std::vector<std::uint8_t>& entry, const EntryParts& parts, std::uint64_t number,
                  bool nextStep, World& world, const EntryFail& fail);

}  // namespace rbsim::app
