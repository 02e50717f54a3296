#pragma once
// The step hook: a system stepped beside the rigid bodies, once a step after they have moved
// (Jolt's PhysicsStepListener). Particles, soft bodies and the 2D world are such systems
// (world/systems.h), so the World knows them only through this seam (docs/architecture.md).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rbsim/body/material.h"
#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/body_solid.h"
#include "rbsim/collision/contact.h"
#include "rbsim/settings/settings.h"

namespace rbsim {

// What a system sees of the World during its step: the rigid bodies where the step left them
// (mutable, for systems that push back, as soft bodies do), their solids and the planes.
struct StepContext {
  double time = 0.0;            // at the start of the step [s]
  std::uint64_t stepCount = 0;  // steps taken before this one
  const Settings& settings;     // timeStep, gravity, detectCollisions, ...
  std::vector<RigidBody>& bodies;
  const std::vector<BodySolid>& shapes;          // per body
  const std::vector<Material>& bodyMaterials;    // per body
  const std::vector<Plane>& planes;
  const std::vector<Material>& planeMaterials;   // per plane
};

class StepListener {
 public:
  virtual ~StepListener() = default;
  // Nothing to step: the stage is skipped when every listener is idle (Settings::skipIdleStages).
  virtual bool idle() const = 0;
  // Advances the system by context.settings.timeStep. Throws SimulationError when it diverges.
  virtual void step(const StepContext& context) = 0;
  // World::destroyBody removed body `removed` and moved body `from` into its index `to`.
  virtual void bodyRemoved(std::size_t removed, std::size_t from, std::size_t to) {
    (void)removed, (void)from, (void)to;
  }
  // FNV-1a over the bits of the system's state, continuing from `hash` (World::stateHash).
  virtual std::uint64_t hashState(std::uint64_t hash) const { return hash; }
  // A deep copy going on alone, for World's copy (a saved state); null: the system cannot be
  // copied, and copying its World throws.
  virtual std::unique_ptr<StepListener> clone() const { return nullptr; }
};

}  // namespace rbsim
