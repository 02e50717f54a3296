#pragma once
// The contacts of sleeping islands, kept apart from the step's (Box2D v3's sleeping solver sets,
// src/solver_set.c: b2TrySleepIsland moves an island's contacts into its set, b2WakeSolverSet
// moves them back). No stage visits them: a step costs its awake bodies and their contacts alone.
// Each contact is filed under its bodies that are neither static nor a plane, so that an island
// is found from any of its bodies by following its contacts (takeIsland).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/contact.h"

namespace rbsim {

class BodyRemoval;

class SleepingContacts {
 public:
  using Lists = std::vector<std::vector<std::uint32_t>>;  // per body: the slots filed under it
  // `lists`: the body table's column for them (world/body_table.h keptContacts), which the table
  // keeps in step with the bodies (grown by an add, gathered by a removal) and this fills.
  explicit SleepingContacts(Lists& lists) : of_(&lists) {}
  // A copy filing under `lists` (a copy of other's table's column).
  SleepingContacts(const SleepingContacts& other, Lists& lists) : SleepingContacts(other) { of_ = &lists; }
  // Empty: no kept contact, every body's list cleared.
  void clear();
  void add(const Contact& contact, const std::vector<RigidBody>& bodies);
  bool holds(std::size_t body) const { return body < of_->size() && !(*of_)[body].empty(); }
  bool empty() const { return live_ == 0; }
  std::size_t size() const { return live_; }
  // The island of each seed, through the kept contacts between bodies that are not static: its
  // bodies (each once, the seeds included) and its contacts, which leave, in key order.
  void takeIslands(const std::vector<std::size_t>& seeds, const std::vector<RigidBody>& bodies,
                   std::vector<std::size_t>& islandBodies, std::vector<Contact>& contacts);
  // Every kept contact, in key order (kind, lower body or plane, higher body, part), appended.
  void all(std::vector<Contact>& out) const;
  // The kept contacts of these bodies (indices), each once, in key order.
  void of(const std::vector<std::uint32_t>& bodies, std::vector<Contact>& out) const;
  // World::destroyBodies, before the table's rows are gathered: the kept contacts of the bodies
  // the removal reached follow them (world/contact_renumbering.h), and a removed body's go (their
  // partners into `touched`, out of their bodies' lists). `reached` gets those contacts as they were, in
  // key order. It costs the reached bodies' contacts, not every kept one (issue 58: removal costs
  // what it touches; Box2D v3's b2DestroyBody walks the body's own contact list).
  void bodiesRemoved(const BodyRemoval& removal, std::vector<std::size_t>& touched, std::vector<Contact>& reached);

 private:
  std::vector<Contact> slots_;
  std::vector<char> used_;                    // per slot
  std::vector<std::uint32_t> free_;           // unused slots
  Lists* of_;                                 // per body: the slots filed under it (the table's)
  std::vector<char> seen_;                    // takeIslands' scratch, per body
  // The slots filed under these bodies, each once, in slot order.
  std::vector<std::uint32_t> slotsOf(const std::uint32_t* first, std::size_t count) const;
  void release(std::uint32_t slot);  // the slot's contact leaves (its lists are the caller's)
  std::size_t live_ = 0;
};

// The order contacts() reports kept contacts in, the same however they were filed.
bool keptBefore(const Contact& x, const Contact& y);

}  // namespace rbsim
