#pragma once
// What tests and the World's own queries read behind World's public surface: its collision
// stages and its contact solver. Private (rbsim::internals); World names it a friend.
#include "dynamics/contact_solver.h"
#include "rbsim/world/world.h"
#include "world/collision_pipeline.h"

namespace rbsim {

struct WorldAccess {
  static const CollisionPipeline& collision(const World& world) { return *world.collision_; }
  static const ContactSolver& solver(const World& world) { return *world.solver_; }
  static QueryTreeCache& queryCache(const World& world) { return world.queryCache_.cache(); }
};

}  // namespace rbsim
