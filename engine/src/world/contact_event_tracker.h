#pragma once
// contactEvents(world) (world/contact_events.h): which pairs of shapes began or stopped touching,
// found by comparing each step's touching pairs with the last step's, as Box3D flags a contact
// that started or stopped touching in its narrow phase (physics_world.c b3UpdateContacts); and
// the hits the solver reports (ContactSolver::hits).
//
// A pair is keyed by what stays put from step to step: its bodies by their broad-phase proxies
// (which outlive the index changes of destroyBody, so a removal renames no pair), a plane by its
// index. The narrow phase lists its contacts in the broad phase's pair order, then plane by plane
// and body by body, which is the keys' order until a removal has moved bodies: each step's keys
// mostly come sorted (a sort is the fallback), and the comparison is one merge, O(contacts), with
// no table. A pair both of whose sides are asleep keeps touching whatever the narrow phase says (a
// sleeping pair of grid bodies is not collided, and an island asleep is not apart).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dynamics/contact_solver.h"
#include "rbsim/world/contact_events.h"

namespace rbsim {

class World;
class CollisionPipeline;
class ByteWriter;  // math/byte_stream.h
class ByteReader;

class ContactEventTracker {
 public:
  // Before each step: whatever a failed attempt left is forgotten.
  void beginStep();
  // After the narrow phase: this step's touching pairs against the last step's, into begin and
  // end events.
  void afterNarrowPhase(const World& world, const CollisionPipeline& collision);
  // After the solver: its hits faster than `speed` (ContactSolver::hits) as events, the first of
  // each pair's touching only. The soft step's speculative contact starts braking a falling body
  // in the step before it lands, so one landing is two steps of impulses (Box3D would report
  // both): the first is the hit, its approach speed the one the pair met with.
  void afterSolve(const World& world, const CollisionPipeline& collision, const std::vector<Contact>& contacts,
                  const ContactSolver& solver, double speed);
  // Body `index` breaks into pieces (World::breakBody), before its proxy is replaced: its pairs end.
  void bodyBroken(const World& world, const CollisionPipeline& collision, std::size_t index);
  // Bodies are destroyed (World::destroyBodies), before their ids go stale: `gone`, their
  // indices, sorted. Their pairs end, with this step's events or, between steps, the next step's.
  void bodiesRemoving(const World& world, const CollisionPipeline& collision, const std::vector<std::uint32_t>& gone);
  // These contacts' island woke (World::wakeIslandsOf): their pairs, kept aside while asleep,
  // touch on among this step's (or, before its narrow phase, the last step's).
  void contactsWoke(const std::vector<Contact>& contacts, const CollisionPipeline& collision);
  // Islands fell asleep at the end of the step (CollisionPipeline::sleepContacts): their touching
  // pairs go aside now, and the others' contacts take their new indices (`newIndex`).
  void contactsSlept(const std::vector<Contact>& contacts, const CollisionPipeline& collision,
                     const std::vector<std::uint32_t>& newIndex);
  // The step succeeded: its events are the World's until the next one succeeds.
  void commit();
  const ContactEvents& events() const { return events_; }
  // The pairs touching after the last step, in a World snapshot (world/world_snapshot.cpp), so
  // that a World read back reports the same events from its next step on. The last step's events
  // and the ends queued by removals between steps are not saved: a World read back has none.
  void save(ByteWriter& out) const;
  // `keyedByIndex`: a snapshot before version 6, whose plane pairs name their body by index: they
  // are renamed to its proxy (`collision` read back first).
  void load(ByteReader& in, bool keyedByIndex, const CollisionPipeline& collision);

 private:
  struct Entry {
    std::uint64_t hi = 0, lo = 0;  // the key: kind and first side; second side and both children
    std::uint32_t contact = 0;     // the contact it came from this step (kNoContact: kept asleep)
    bool swapped = false;          // A is the second side of the key (the begin named it so)
    bool hit = false;              // a hit was reported since the pair began touching
    bool operator<(const Entry& o) const { return hi != o.hi ? hi < o.hi : lo < o.lo; }
    bool sameKey(const Entry& o) const { return hi == o.hi && lo == o.lo; }
  };
  static constexpr std::uint32_t kNoContact = UINT32_MAX;

  static Entry keyOf(const Contact& contact, const CollisionPipeline& collision);
  ContactPair pairOf(const Entry& entry, const World& world, const CollisionPipeline& collision) const;
  bool asleep(const Entry& entry, const World& world, const CollisionPipeline& collision) const;
  // The entries of `list` naming a body for which `names` is true leave it for `taken`, in order.
  template <typename Names>
  static void takeWhere(std::vector<Entry>& list, const CollisionPipeline& collision, Names&& names,
                        std::vector<Entry>& taken);

  std::vector<Entry> touching_;  // after the last step, sorted by key, but for asleep_
  // The touching pairs both of whose sides sleep (issue 58: a step visits awake pairs alone), by
  // key, until their island wakes.
  // A hash map: the narrow phase, a wake or a removal looks up a few in one probe each.
  struct KeyHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const {
      return std::hash<std::uint64_t>()(k.first * 0x9e3779b97f4a7c15ull ^ k.second);  // Fibonacci mix of both halves
    }
  };
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, Entry, KeyHash> asleep_;
  std::vector<Entry> keys_;      // this step's contacts' keys (scratch)
  std::vector<Entry> next_;      // this step's touching pairs, sorted
  std::vector<ContactHit> hits_;  // the solver's (scratch)
  bool haveNext_ = false;        // next_ is this step's (the narrow phase ran)
  ContactEvents step_;           // this step's events so far
  std::vector<ContactEndEvent> queuedEnds_;  // of bodies removed since the last step began
  ContactEvents events_;         // the last successful step's
};

}  // namespace rbsim
