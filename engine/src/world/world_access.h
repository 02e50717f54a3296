#pragma once
// The World's members behind its public surface, for the free functions over World (queries,
// spawners and the kill volume, kinematic motions, body, joint and spring changes: their own
// headers, docs/architecture.md "The World's surface") and for tests. Private (rbsim::internals);
// World names it a friend.
#include "dynamics/contact_solver.h"
#include "rbsim/world/world.h"
#include "world/collision_pipeline.h"
#include "world/contact_event_tracker.h"

namespace rbsim {

struct WorldAccess {
  static const CollisionPipeline& collision(const World& world) { return *world.collision_; }
  static const ContactSolver& solver(const World& world) { return *world.solver_; }
  static QueryTreeCache& queryCache(const World& world) { return world.queryCache_.cache(); }
  static const ContactEventTracker& contactEvents(const World& world) { return *world.contactEvents_; }

  // Every per-body column and the ids (world/body_table.h).
  static const BodyTable& table(const World& world) { return *world.table_; }
  // What the free functions change (and read).
  static std::vector<RigidBody>& bodies(World& world) { return world.table_->bodies; }
  static std::vector<Material>& bodyMaterials(World& world) { return world.table_->materials; }
  static const std::vector<Material>& bodyMaterials(const World& world) { return world.table_->materials; }
  static const std::vector<Material>& planeMaterials(const World& world) { return world.planeMaterials_; }
  static const std::vector<BodySolid>& bodySolids(const World& world) { return world.table_->solids; }
  static const std::vector<FractureEvent>& fractureEvents(const World& world) { return world.fractureEvents_; }
  static const std::vector<ScriptedForce>& forces(const World& world) { return world.forces_; }
  static std::vector<Spring>& springs(World& world) { return world.springs_; }
  static const std::vector<Spring>& springs(const World& world) { return world.springs_; }
  static std::vector<Joint>& joints(World& world) { return world.joints_; }
  static IdTable<SpringId>& springIds(World& world) { return world.springIds_; }
  static const IdTable<SpringId>& springIds(const World& world) { return world.springIds_; }
  static IdTable<JointId>& jointIds(World& world) { return world.jointIds_; }
  // The shapes' ids (world/shape_table.h), and the id of bodies()[index]'s child `child`.
  static const ShapeTable& shapeIds(const World& world) { return world.table_->shapeIds; }
  static ShapeId shapeIdOf(const World& world, std::size_t index, std::size_t child) {
    return world.table_->shapeIds.idOf(world.bodyKeys()[index], child);
  }
  static BodyId bodyIdOfSlot(const World& world, std::uint32_t slot) { return {slot, world.table_->ids.slots()[slot].generation}; }
  static const IdTable<JointId>& jointIds(const World& world) { return world.jointIds_; }
  static std::vector<KinematicMotion>& motions(World& world) { return world.motions_; }
  static const std::vector<KinematicMotion>& motions(const World& world) { return world.motions_; }
  static std::vector<Spawner>& spawners(World& world) { return world.spawners_; }
  static const std::vector<Spawner>& spawners(const World& world) { return world.spawners_; }
  static Aabb& killVolume(World& world) { return world.killVolume_; }
  static const Aabb& killVolume(const World& world) { return world.killVolume_; }
  static const std::vector<BodyId>& spawnedNow(const World& world) { return world.spawnedNow_; }
  static const std::vector<BodyId>& removedNow(const World& world) { return world.removedNow_; }
  static std::uint64_t& geometryVersion(World& world) { return world.geometryVersion_; }
  static std::uint64_t geometryVersion(const World& world) { return world.geometryVersion_; }
  static void updateJointFilter(World& world) { world.updateJointFilter(); }
  static void wakeBody(World& world, std::size_t index) { world.wakeBody(index); }  // and lists it awake
};

}  // namespace rbsim
