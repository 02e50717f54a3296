#pragma once
// Particles, soft bodies and the 2D world: systems beside the rigid bodies. Each lives in the
// World as a StepListener (dynamics/step_listener.h) and is stepped by its StepSystems stage, in
// the order the systems were first added; world.h knows none of them (docs/architecture.md).
#include <cstddef>
#include <vector>

#include "rbsim/particles/particle_system.h"
#include "rbsim/planar/planar_world.h"
#include "rbsim/soft/soft_body.h"
#include "rbsim/world/world.h"

namespace rbsim {

// Throws std::invalid_argument when checkParticleSystemDef finds a problem.
std::size_t addParticleSystem(World& world, const ParticleSystemDef& def);
const std::vector<ParticleSystem>& particleSystems(const World& world);  // empty when none
std::vector<ParticleSystem>& particleSystems(World& world);  // adds an empty, idle system when none

// FEM soft bodies; throws std::invalid_argument on a bad definition (SoftBody's constructor).
std::size_t addSoftBody(World& world, const SoftBodyDef& def);
const std::vector<SoftBody>& softBodies(const World& world);  // empty when none
std::vector<SoftBody>& softBodies(World& world);  // adds an empty, idle system when none

// A 2D world stepped with the World's dt and the x, y components of its gravity; replaces the
// one there was.
void setPlanarWorld(World& world, const PlanarWorld& planar);
const PlanarWorld* planarWorld(const World& world);  // null when none
PlanarWorld* planarWorld(World& world);  // the same, to set its bodies' states (a replay)

}  // namespace rbsim
