#pragma once
// The World's bodies as one table (issue 58; Box2D v3's b2SolverSet keeps each body's b2BodySim
// and b2BodyState in arrays of one set, src/solver_set.c): every per-body column, row i being
// bodies()[i], with the ids that name the rows. One owner, one add and one removal: a column is
// never resized anywhere else, so a column cannot fall out of step with the others when a body
// comes or goes. The World and its collision pipeline read and write the rows; only add, retire
// and gather change how many there are.
//
// Rows, not slots: a removal swap-removes, the last body taking the removed one's row, as
// destroyBody always has (bodies() stays dense, so every pass runs over a plain array); the ids
// keep each body's slot, which pairs, warm starts and joints are keyed by (dynamics/contact_key.h).
// Scratch arrays that a stage refills each step (UpdateSleep's local indices, BreakBodies'
// impulses) are not columns: nothing reads them across a step.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rbsim/body/body_id.h"
#include "rbsim/body/id_table.h"
#include "rbsim/body/material.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/broadphase/broad_phase.h"
#include "rbsim/geometry/aabb.h"
#include "rbsim/integrate/body_state.h"
#include "rbsim/world/shape_table.h"

namespace rbsim {

struct FracturePattern;  // fracture/fracture.h
class BodyRemoval;       // a batch of removals (engine/src/body/body_removal.h)

struct BodyTable {
  // The World's columns.
  std::vector<RigidBody> bodies;
  std::vector<Material> materials;
  std::vector<BodySolid> solids;
  std::vector<std::shared_ptr<const FracturePattern>> fracturePatterns;  // null: unbreakable
  std::vector<char> listed;  // in the World's awake list (world/awake_bodies.cpp)

  // The collision pipeline's columns (world/collision_pipeline.h), filled by its addBody.
  std::vector<ProxyId> proxies;  // the body's broad-phase proxy
  std::vector<double> radius;     // farthest point of the collision shape from the centre of mass [m]
  std::vector<double> thickness;  // smallest extent of its body-frame bounds [m]
  // How far its points may move in the coming step, dt (|v| + |omega| radius + dt |g|). Added to
  // the contact margin, so that a contact is known (speculative, depth < 0) before the surfaces
  // meet (as Bepu's and Jolt's speculative contacts) [m]. PGS, which detects contacts after it
  // moved the bodies, needs them as much: a box tumbling at 20 rad/s swings a corner 10 cm a
  // step, continuous collision stopped it at the corner's impact every step, and with no contact
  // to take its speed the box gained g dt of it each step (5 kJ in examples/python/falling_stack.py).
  std::vector<double> reach;
  std::vector<BodyState> start;  // before Integrate, for the continuous stage
  std::vector<char> fast;        // swept this step
  // Shaped by a grid, or compound. Continuous collision sweeps convex hulls, so it leaves such
  // bodies and their partners alone (a hull would stop a body at a bowl's rim, above its cavity,
  // or at a table's hull, under its top).
  std::vector<char> hasGrid;
  // A static triangle-mesh ground (world/mesh_ground_contacts.h), also marked in hasGrid: its
  // convex hull would stop a body above its valleys.
  std::vector<char> meshGround;
  // How far its solid may reach beyond its display mesh's vertices [m] (an implicit body's: a
  // cell's diagonal), added to its box.
  std::vector<double> gap;
  std::vector<Aabb> boxes;       // as last given to the broad phase
  // The slots of the sleeping contacts filed under the body (world/sleeping_contacts.h).
  std::vector<std::vector<std::uint32_t>> keptContacts;

  // Per slot the row and generation of the body there, per row its slot (body/body_id.h).
  IdTable<BodyId> ids;
  ShapeTable shapeIds;  // the bodies' shapes' ids, by body id slot (world/shape_table.h)

  std::size_t size() const { return bodies.size(); }
  // Per row, its stable key (its id's slot): what pairs and warm starts are named by.
  const std::vector<std::uint32_t>& keys() const { return ids.slotOfItem(); }

  // Appends a row: the body made from `def`, its material, solid and fracture pattern, a new id
  // and its shapes' ids, and in every other column a default that its owner fills
  // (CollisionPipeline::addBody). Returns the body's id.
  BodyId add(const BodyDef& def);
  // The first half of a removal: the ids go stale, as destroyBody one after another retires them
  // (each slot's generation moves on, the last row takes the removed one's, keeping its slot), and
  // their shapes' ids with them. Returns the removal, for the World's parts to read the rows they
  // hold before gather (ids valid and distinct).
  BodyRemoval retire(const std::vector<BodyId>& ids);
  // The second half: every column brought to the rows after the removal (BodyRemoval::gather).
  void gather(const BodyRemoval& removal);

 private:
  // Every per-row column, to `fn` in turn; sizeof(BodyTable) is checked against their count in
  // body_table.cpp, so that a column added above and left out here fails the build.
  template <typename Fn>
  void forEachColumn(Fn&& fn);
};

}  // namespace rbsim
