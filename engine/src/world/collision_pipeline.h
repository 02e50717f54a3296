#pragma once
// The collision stages of World::step (seed 004 "two-phase collision detection"): continuous
// collision for fast bodies, the broad phase over world AABBs, and the narrow phase turning
// candidate pairs and planes into contact manifolds. Owned by the World; plain data out.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/collision/contact.h"
#include "rbsim/collision/impact.h"
#include "rbsim/collision/narrowphase/query_log.h"
#include "rbsim/settings/settings.h"
#include "rbsim/world/body_table.h"
#include "math/key_index.h"
#include "world/contact_recycling.h"
#include "world/sleeping_contacts.h"
#include "world/split_broad_phase.h"

namespace rbsim {

// The body's bounding box where it is (collision_pipeline_bodies.cpp): a round shape's exact one
// (its display mesh is inscribed in it), a compound's children's, the vertices' for the others,
// whose shape is the hull of those vertices.
Aabb bodyBounds(const RigidBody& body);

class BodyRemoval;  // body/body_removal.h
class ByteWriter;   // math/byte_stream.h
class ByteReader;

class CollisionPipeline {
 public:
  // Its per-body columns live in `table` (world/body_table.h: the proxies, reach, boxes, ...),
  // which it fills as bodies are added and which the table keeps in step with the bodies; the
  // table must outlive it (the World holds both).
  CollisionPipeline(const Settings& settings, BodyTable& table);
  // A deep copy (World's copy): its broad phase, contacts and kept sleeping contacts too, over
  // `table`, the copy of other's table.
  CollisionPipeline(const CollisionPipeline& other, BodyTable& table);
  CollisionPipeline& operator=(const CollisionPipeline&) = delete;
  // World::setSettings: every setting but the broad phase method, which the World refuses to change.
  void setSettings(const Settings& settings) { settings_ = settings; }

  // Body `index`, the table's last row, was added (BodyTable::add): its measures, box and proxy
  // from its body and solid (a body with a grid, BodySolid::sdf, is not its convex hull; an
  // implicit body's display mesh lies up to a cell inside its exact surface).
  void addBody(std::size_t index);
  // Bodies are being destroyed (World::destroyBodies, body/body_removal.h), the table's rows not
  // yet gathered: their proxies and contacts go, the moved bodies' are renumbered, and the last
  // step's impacts are forgotten. `touched` gets the
  // bodies (indices before the removal) that a removed body touched, to be woken; `reached` the
  // sleeping islands' contacts of the bodies the removal reached, as they were (the removed
  // bodies' name the warm starts kept aside that go with them: ContactSolver::bodiesRemoved). A sleeping island's contacts are visited only
  // when a reached body holds them; the step's, all (a step visits them anyway).
  void removeBodies(const BodyRemoval& removal, std::vector<std::size_t>& touched, std::vector<Contact>& reached);
  // The sleeping islands' contacts of these bodies (indices), each once, in key order.
  void keptContactsOf(const std::vector<std::uint32_t>& bodies, std::vector<Contact>& out) const { sleeping_.of(bodies, out); }
  // Body `index` was replaced in the table by another (a piece of it, after fracture): its proxy,
  // box and bounds are rebuilt, and it may have stopped being static.
  void replaceBody(std::size_t index);

  // A World snapshot (world/world_snapshot.h; collision_pipeline_snapshot.cpp): what the next
  // step reads of the last one, that the bodies alone do not give: the proxies' ids and boxes,
  // the reach and start of each body, this step's contacts, the recycling frames and their index.
  // load() reads into a pipeline whose table holds the same bodies, added in order (their
  // measures), and rebuilds the broad phase with the same ids: its pairs are those of the boxes,
  // whatever path its updates took (broad_phase.h). `planes`: how many the World has.
  void save(ByteWriter& out) const;
  void load(ByteReader& in, std::size_t planes);

  // Pairs of bodies that never collide (jointed bodies without collide_connected): body indices,
  // either order. The narrow phase skips them.
  void setIgnoredPairs(const std::vector<std::pair<std::size_t, std::size_t>>& pairs);
  // One more pair that must not collide; sorted in with the others before the next narrow phase,
  // so adding n joints costs n log n, not n^2 (a 100 x 100 joint grid loaded in 5 s).
  void ignorePair(std::size_t a, std::size_t b);

  // The passes below read and write the table's bodies (table_->bodies, its solids and keys); they
  // visit the `awake` bodies (World's awakeList_: indices in order) and the sleeping or static
  // bodies their boxes meet, never every body (issue 58).
  // The state of every awake body before Integrate, kept for the continuous stage.
  void rememberStart(const std::vector<std::uint32_t>& awake);
  // Stage ContinuousCollision: fast bodies that would pass through a plane or a body this step
  // are moved back to their time of impact. Returns the impacts of this step.
  // `solved`: per body, nonzero when a contact solver already moved it through speculative
  // contacts this step (soft step); those are left alone. Null: none was.
  void continuous(const std::vector<std::uint32_t>& awake, const std::vector<Plane>& planes,
                  const std::vector<char>* solved = nullptr);
  // Stage BroadPhase: every moved body's AABB (inflated by the contact margin; swept for fast
  // bodies) into the broad phase, then the candidate pairs.
  void broadPhase(const std::vector<std::uint32_t>& awake);
  // Stage NarrowPhase: contacts of candidate pairs and of awake bodies against planes. Sleeping
  // bodies are not collided with each other or with planes: the last step's contacts whose bodies
  // all sleep now are kept apart (sleeping_; listed in sleptNow()), as they were (nothing of
  // theirs has moved since), until their island wakes (takeIslands).
  // Pairs with a signed distance grid use the table's solids; the table's keys (World's
  // bodyKeys) order each pair (bodiesOf).
  void narrowPhase(const std::vector<std::uint32_t>& awake, const std::vector<Plane>& planes, double time);
  const std::vector<Contact>& sleptNow() const { return sleptNow_; }  // the last narrow phase's
  // Islands fell asleep at the end of a step (World::updateSleep): their contacts leave the step's
  // for sleeping_ now (listed in sleptNow()), as Box2D v3's b2TrySleepIsland moves an island's
  // contacts into its solver set, so that nothing after the step (a removal, the next step) visits
  // them. `newIndex` gets, per contact of the step before, its index after, or kNoContact.
  static constexpr std::uint32_t kNoContact = UINT32_MAX;
  void sleepContacts(std::vector<std::uint32_t>& newIndex);
  // Whether body `index` has kept contacts (it sleeps, or woke since and its island has not).
  bool keepsContactsOf(std::size_t index) const { return sleeping_.holds(index); }
  // The islands of `seeds` (SleepingContacts::takeIslands): their bodies, to be woken, and their
  // kept contacts, which leave.
  void takeIslands(const std::vector<std::size_t>& seeds, std::vector<std::size_t>& islandBodies,
                   std::vector<Contact>& contacts);
  // Contacts of an island woken after the narrow phase, solved with this step's.
  void appendContacts(const std::vector<Contact>& more) {
    contacts_.insert(contacts_.end(), more.begin(), more.end());
    reportedStale_ = true;
  }

  // Something awake and something to meet: two bodies, or a body and a plane. The stage also
  // refreshes boxes(), which the plane tests of the narrow phase read.
  bool needsBroadPhase(const std::vector<std::uint32_t>& awake, const std::vector<Plane>& planes) const;
  // Broad-phase proxy ids: the bodies' indices until a body is destroyed, bodyOfProxy after.
  const std::vector<ProxyPair>& candidatePairs() const { return broad_->pairs(); }
  const std::vector<ProxyId>& broadPhaseAwake() const { return broad_->awakeAtUpdate(); }  // the awake proxies
  std::size_t bodyOfProxy(ProxyId proxy) const { return bodyOfProxy_.at(proxy); }
  ProxyId proxyOf(std::size_t body) const { return table_->proxies[body]; }  // kept while the body lives
  std::size_t bodyCount() const { return table_->proxies.size(); }
  // This step's contacts: those of the awake bodies, the solver's (then those of islands woken
  // after the narrow phase).
  const std::vector<Contact>& contacts() const { return contacts_; }
  // World::contacts(): this step's, then the kept contacts of sleeping islands in key order
  // (keptBefore), gathered when asked after a change, never by a step.
  const std::vector<Contact>& reported() const;
  // Of this step's contacts, how many were recycled rather than collided (Box3D's profile count).
  std::size_t recycledCount() const { return recycledCount_; }
  const std::vector<Impact>& impacts() const { return impacts_; }
  const std::vector<Aabb>& boxes() const { return table_->boxes; }  // per body, as last given to the broad phase
  const QueryLog& queryLog() const { return log_; }

 private:
  bool isFast(std::size_t body) const;
  // Into `out`, in index order: the bodies whose box may meet `box` (every awake body, and the
  // sleeping and static ones whose box does).
  void nearSweep(const Aabb& box, const std::vector<std::uint32_t>& awake, std::vector<std::size_t>& out) const;
  // What collidePair left for later: nothing, a pair with a grid (collided on the calling
  // thread: it gives several manifolds), a pair with a compound body or a body on a mesh ground
  // (both into compoundSlots_, several contacts a pair).
  enum class Later : char { Nothing, Grid, Compound, MeshGround };
  // The convex or round contact of candidate pair `proxies` into `out` (count 0: none, or a pair
  // to skip), or what is left for later.
  Later collidePair(const ProxyPair& proxies, double time, Contact& out, RecycleFrame& frame);
  // A candidate pair's bodies (indices) in the order its contacts name them: the lower stable key
  // first (the table's keys, World's bodyKeys: the BodyId slots). A removal moves bodies to new
  // indices but leaves their keys, so it never turns a pair round (Box2D v3 orders a contact's
  // shapes by id).
  ProxyPair bodiesOf(const ProxyPair& proxies) const;
  // The pairs collidePair left to the compound and mesh-ground pass, on `threads` threads into
  // compoundSlots_.
  void collideCompounds(const std::vector<ProxyPair>& pairs, int threads);
  void measure(std::size_t index, const RigidBody& body, const BodySolid& solid);  // a row's radius, thickness, box, ...
  static std::uint64_t keptKey(Contact::Kind kind, std::size_t a, std::size_t b);
  // The last step's contacts whose bodies all sleep now go to sleeping_ (and sleptNow_).
  void keepSleeping();
  // Whether contact `c` is kept apart while its bodies sleep: they all sleep, and it comes back
  // whole when they wake (a grid pair's manifolds are found afresh instead).
  bool keptAsleep(const Contact& c) const;
  // Contact recycling (world/contact_recycling.h): the manifold of the pair (kind, a, b) rebuilt
  // from the frame it was computed in, if it had one and has moved little enough since; `frame`
  // gets the frame the contact now carries.
  std::optional<ContactManifold> recycled(Contact::Kind kind, std::size_t a, std::size_t b, const RecyclePose& poseA,
                                          const RecyclePose& poseB, RecycleFrame& frame) const;
  RecyclePose poseOf(const RigidBody& body, std::size_t index) const { return {body.position(), body.orientation(), table_->radius[index]}; }
  // The frames of this step's recyclable contacts, indexed by key, for the next step.
  void keepFrames();

  Settings settings_;
  BodyTable* table_;  // the World's: the per-body columns this pipeline keeps there
  std::unique_ptr<SplitBroadPhase> broad_;  // the awake proxies' pairs, with the resting ones
  std::vector<ProxyId> awakeProxies_;       // broadPhase's scratch
  std::vector<std::size_t> bodyOfProxy_;  // per broad-phase proxy id: its body's index
  std::vector<std::size_t> fastList_;   // the bodies the table's fast column marks, in order
  std::vector<Aabb> stepBoxes_;         // continuous's scratch, per awake body: its box over the step
  std::vector<std::size_t> near_;       // continuous's scratch: the bodies near a sweep, in order
  mutable std::vector<ProxyId> restingNear_;  // nearSweep's scratch
  bool haveStart_ = false;              // the table's start column holds this step's (rememberStart ran)
  std::vector<std::uint64_t> ignored_;  // sorted keys (lower index << 32 | higher index)
  bool ignoredSorted_ = true;           // false after ignorePair until the next narrow phase
  std::vector<Contact> contacts_;
  // The contacts of sleeping islands, and those that went there in the last narrow phase.
  SleepingContacts sleeping_;
  std::vector<Contact> sleptNow_;
  mutable std::vector<Contact> reported_;  // reported(), when sleeping_ holds some
  mutable bool reportedStale_ = true;
  // Per candidate pair and per (plane, body): this step's contact, computed on any thread into its
  // own slot and gathered in order (manifold.count 0: none). later_ marks the pairs collided
  // after them.
  std::vector<Contact> pairSlots_, planeSlots_;
  // Per slot: the recycling frame of its contact (count 0: none, a contact that is not recycled).
  std::vector<RecycleFrame> pairFrames_, planeFrames_;
  // The last step's frames (pairFrames_ and planeFrames_ as they were), and the index of those
  // that may be recycled: by keptKey, to a pair slot k, or to pairs + k for a plane slot k.
  std::vector<RecycleFrame> keptPairFrames_, keptPlaneFrames_;
  KeyIndex recycle_;
  std::size_t recycledCount_ = 0;
  double recycleTolerance_ = 0.0;  // recycleDistance(settings_) of this narrow phase [m]
  std::vector<Later> later_;
  // Per candidate pair and per (plane, body) with a compound body: its contacts, one per pair of
  // children, computed on any thread into their own slot.
  std::vector<std::vector<Contact>> compoundSlots_, compoundPlaneSlots_;
  std::vector<std::size_t> compoundWork_;  // this step's pairs, then (plane, body) items, with a compound
  std::vector<Impact> impacts_;
  QueryLog log_;
};

}  // namespace rbsim
