#pragma once
// The seam between World::step and the contact solvers (stage SolveContacts), as the broad phase
// keeps sweep and prune beside brute force: SoftStepSolver (soft_step_solver.h) is the default,
// PgsSolver (pgs_solver.h) the reference, LcpSolver (lcp_solver.h) the exact one for small scenes
// (seed 001's resting contact as a linear complementarity problem, issue 55). The World picks one
// from Settings::solver when it is built (makeContactSolver) and asks it where in the step it
// goes. A new solver implements this class and adds a Settings::ContactSolverMethod
// (docs/architecture.md, "Adding a solver").
#include <cstddef>
#include <memory>
#include <vector>

#include "rbsim/body/id_table.h"
#include "rbsim/body/material.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/contact.h"
#include "rbsim/dynamics/joint.h"
#include "rbsim/dynamics/solved_contact_point.h"
#include "rbsim/settings/settings.h"

namespace rbsim {

// What stage SolveContacts hands the solver. `bodyMaterials` has one entry per body,
// `planeMaterials` one per plane; `addGravity`: the forces accumulated in the bodies lack m g
// (World::step adds gravity in its Integrate pass unless other forces act).
class ByteWriter;   // math/byte_stream.h
class ByteReader;

struct SolverInput {
  std::vector<RigidBody>& bodies;
  const std::vector<Contact>& contacts;
  std::vector<Joint>& joints;
  // The bodies' ids: a joint's body's index is bodyIds.indexOf(id); a body's stable key (its slot,
  // which a removal leaves as it was), what the warm starts are keyed by (contact_key.h pairKey),
  // is bodyIds.slotOfItem()[index].
  const IdTable<BodyId>& bodyIds;
  const std::vector<Material>& bodyMaterials;
  const std::vector<Material>& planeMaterials;
  const Settings& settings;
  bool addGravity = true;
};

// A manifold of the last solve that was hit (Box3D's hit events, src/solver.c and
// contact_solver.c): a point took a normal impulse while the bodies approached along the normal,
// before the solve, faster than a speed. The speculative points that took none only came near.
struct ContactHit {
  std::size_t contact = 0;         // index into the contacts solved
  Vec3 point = Vec3::Zero();       // the fastest such point [m]
  double approachSpeed = 0.0;      // -u_rel,N there before the solve [m/s]
};

// The material of a contact: the two sides' (a compound body's touching child's), combined.
inline Material contactMaterial(const SolverInput& input, const Contact& contact) {
  const auto of = [&](std::size_t body, std::uint16_t child) -> const Material& {
    const RigidBody& b = input.bodies[body];
    return b.isCompound() ? b.children()[child].material : input.bodyMaterials[body];
  };
  const bool plane = contact.kind == Contact::Kind::PlaneBody;
  return combine(of(contact.b, contact.childB), plane ? input.planeMaterials[contact.a] : of(contact.a, contact.childA));
}

class ContactSolver {
 public:
  // The two orders of World::step's middle stages.
  enum class Order {
    // Collide at the poses the last step left, then the solver advances the bodies it finds in
    // contact or jointed, and the integrator the rest (Box2D v3's b2Collide before b2Solve).
    CollideFirst,
    // Integrate every body, then collide and answer the contacts of the new poses with impulses
    // on the integrated velocities (Catto, GDC 2005).
    IntegrateFirst,
  };

  virtual ~ContactSolver() = default;
  virtual Order order() const = 0;
  virtual bool solvesJoints() const = 0;  // false: World::addJoint refuses joints
  virtual void solve(const SolverInput& input) = 0;
  // Every contact point of the last solve with the impulse it received.
  virtual const std::vector<SolvedContactPoint>& points() const = 0;
  // The manifolds of the last solve hit faster than Settings::hitEventSpeed, in contact order,
  // appended to `out`. This one reads points(); a solver whose points are built only when asked
  // keeps its hits as it solves (the soft step: soft_step_finish.cpp).
  virtual void hits(double speed, std::vector<ContactHit>& out) const;
  // Forgets the warm starts and which bodies the last step advanced (bodies were renumbered).
  virtual void forget() = 0;
  // Bodies were destroyed and others moved into their indices (World::destroyBodies,
  // body/body_removal.h). Warm starts are keyed by the bodies' stable keys, so only those naming a
  // removed body go: `removed`, the removed bodies' keys, sorted; `goneAsleep`, the pairKeys of
  // their sleeping islands' contacts (CollisionPipeline::removeBodies), whose warm starts were kept
  // aside (contactsSlept): no other sleeping one is visited. Which bodies the last step advanced
  // is forgotten.
  virtual void bodiesRemoved(const std::vector<std::uint32_t>& removed, const std::vector<std::uint64_t>& goneAsleep) = 0;
  // A deep copy, warm starts included (World's copy, a saved state).
  virtual std::unique_ptr<ContactSolver> clone() const = 0;
  // A World snapshot (world/world_snapshot.h; Jolt's ContactConstraintManager::SaveState): what
  // the next solve reads of the last one (the warm starts, the bodies it advanced, its contact
  // points), for a World whose bodies have these keys (SolverInput::bodyIds). `keyedByIndex`: the
  // saved warm starts name bodies by index (snapshots before version 6), renamed to keys on load.
  // The default refuses, naming the solver: a solver whose state has no saved form
  // (dynamics/solver_snapshot.cpp).
  virtual void save(ByteWriter& out) const;
  virtual void load(ByteReader& in, const std::vector<std::uint32_t>& bodyKeys, bool keyedByIndex);

  // Order::CollideFirst: the World bodies the last solve advanced, which the integrator must
  // leave alone, as a list and as flags per body. Empty for a solver that advances none.
  virtual const std::vector<std::size_t>& advancedBodies() const { return kNone; }
  virtual const std::vector<char>& advancedFlags() const { return kNoFlags; }
  // A step that does not run the solver advances no body.
  virtual void clearAdvanced() {}
  // Sleeping islands (world/sleeping_contacts.h; Box2D's sleeping solver sets keep their
  // contacts' impulses): these contacts of the last solve now sleep, kept apart and not given to
  // solve(); the solver keeps their warm starts aside. contactsWoke: they are awake again, and
  // their warm starts serve the next solve. The default keeps none (a sleeping pair starts cold).
  // `bodyKeys`: SolverInput::bodyIds.slotOfItem().
  virtual void contactsSlept(const std::vector<Contact>& /*contacts*/, const std::vector<std::uint32_t>& /*bodyKeys*/) {}
  virtual void contactsWoke(const std::vector<Contact>& /*contacts*/, const std::vector<std::uint32_t>& /*bodyKeys*/) {}
  // Islands fell asleep at the end of the step and their contacts left the step's
  // (CollisionPipeline::sleepContacts): `newIndex`, per contact the solve was given, its index now
  // or kDroppedContact. The points reported follow; the slept contacts' leave the report, as a
  // sleeping pair's are not reported (it is not solved).
  virtual void contactsReindexed(const std::vector<std::uint32_t>& newIndex) = 0;
  static constexpr std::uint32_t kDroppedContact = UINT32_MAX;

 protected:
  // The points of the contacts kept, renamed by `newIndex`, in order.
  static void reindexPoints(std::vector<SolvedContactPoint>& points, const std::vector<std::uint32_t>& newIndex);

 private:
  static inline const std::vector<std::size_t> kNone{};
  static inline const std::vector<char> kNoFlags{};
};

std::unique_ptr<ContactSolver> makeContactSolver(Settings::ContactSolverMethod method);

}  // namespace rbsim
