#pragma once
// One particle system: its particles (structure of arrays), emitters, springs and the step that
// moves them by F = ma (seed 000's homework: "Build a particle system based either on F = ma or
// procedural simulation"). Lives in the World next to the rigid bodies (world/systems.h) and is
// stepped by its StepSystems stage after the bodies have moved, so particles meet bodies where they are.
#include <cstdint>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/collision/contact.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/particles/emitter.h"
#include "rbsim/particles/particle_collision.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/particles/particle_forces.h"
#include "rbsim/particles/particle_store.h"

namespace rbsim {

class ParticleSystem {
 public:
  // Throws std::invalid_argument when checkParticleSystemDef finds a problem. Makes all storage:
  // the step allocates nothing (except a shape for each rigid body added to the World later).
  ParticleSystem(const ParticleSystemDef& def, const std::vector<RigidBody>& bodies);

  // Advances by dt from time t: emitters add what is due, then def().substeps steps of dt /
  // substeps each apply forces, integrate, collide and age the particles; the expired die.
  // In the step a velocity stops being finite, and every kDivergenceCheckInterval steps for speeds
  // beyond 1e154 m/s, throws SimulationError naming the system, a particle and the integrator.
  void step(double t, double dt, const Vec3& gravity, const std::vector<RigidBody>& bodies,
            const std::vector<BodySolid>& shapes, const std::vector<Plane>& planes);

  const ParticleSystemDef& def() const { return def_; }
  const ParticleStore& particles() const { return store_; }
  ParticleStore& particles() { return store_; }  // for tests and benchmarks that place particles
  const std::vector<ParticleSpring>& springs() const { return springs_; }
  const std::vector<Triangle>& clothTriangles() const { return clothTriangles_; }  // into particles
  std::uint64_t emitted() const { return emitted_; }  // particles born so far
  std::uint64_t lost() const { return lost_; }        // births refused because the store was full

  // World::destroyBody removed body `removed` and moved body `from` into its index `to`.
  void bodyRemoved(std::size_t removed, std::size_t from, std::size_t to) {
    for (Emitter& e : emitters_) e.bodyRemoved(removed, from, to);
  }

  // FNV-1a over the bits of every live particle's x, v and age, continuing from `hash`.
  std::uint64_t hashState(std::uint64_t hash) const;

 private:
  // False when a velocity stopped being finite (checkFinite then finds and names the particle).
  bool substep(double t, double h, const Vec3& gravity, const std::vector<RigidBody>& bodies,
               const std::vector<BodySolid>& shapes, const std::vector<Plane>& planes);
  // A pass of its own over the velocities, made every few steps: the same test inside the step's
  // pass cost 17 % of a step (bench/particle_bench), this one costs 24 B per particle every
  // kDivergenceCheckInterval steps, about 1 % of the step's 128 B.
  void checkFinite(double t, double dt) const;
  static constexpr std::uint64_t kDivergenceCheckInterval = 16;  // [steps], 1/15 s at 240 steps/s

  ParticleSystemDef def_;
  ParticleStore store_;
  UniformRandom random_;
  std::vector<Emitter> emitters_;
  std::vector<ParticleSpring> springs_;
  std::vector<Triangle> clothTriangles_;
  std::vector<Vec3> force_;          // pair forces (springs, flocking) of the current substep [N]
  std::uint64_t steps_ = 0;
  std::uint64_t emitted_ = 0;
  std::uint64_t lost_ = 0;
};

}  // namespace rbsim
