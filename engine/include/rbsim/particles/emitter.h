#pragma once
// Emitters: where particles are born and with what initial conditions (seed 000's homework:
// a particle system's sources). Every random draw comes from the system's seeded generator, in a
// fixed order, so a scene gives the same particles on every run.
#include <cstddef>
#include <memory>
#include <vector>

#include "rbsim/body/rigid_body.h"
#include "rbsim/math/uniform_random.h"
#include "rbsim/particles/particle_def.h"
#include "rbsim/particles/particle_store.h"

namespace rbsim {

class Emitter {
 public:
  // `bodies` gives the mesh-surface emitter its body's mesh, which the emitter keeps (shared) with
  // the triangles' areas for sampling. Throws std::invalid_argument when that surface has no
  // finite, positive area.
  Emitter(const EmitterDef& def, const std::vector<RigidBody>& bodies);

  // Emits what is due during the step [t, t + dt): the burst when the emitter starts, and
  // rate dt particles, the fraction carried to the next step. Returns the particles that found
  // no free slot (the store was full). A mesh-surface emitter whose body has broken (World stage
  // BreakBodies gives the body's index to its first piece, with a mesh of its own) emits nothing
  // from then on: the surface it was made for is gone, and no piece is "the body" more than
  // another. It never reads the pieces' meshes through the triangles of the one it kept.
  std::size_t emit(double t, double dt, ParticleStore& store, UniformRandom& random,
                   const std::vector<RigidBody>& bodies);

  const EmitterDef& def() const { return def_; }

  // The World destroyed a body (World::destroyBody): an emitter on it stops, as after a fracture;
  // one on the body moved into its place (`from`, the last) follows it to `to`.
  void bodyRemoved(std::size_t removed, std::size_t from, std::size_t to) {
    if (def_.shape != EmitterShape::MeshSurface) return;
    if (def_.body == removed) mesh_.reset();
    else if (def_.body == from) def_.body = to;
  }

 private:
  // False once a mesh-surface emitter's body no longer has the mesh the emitter was made for.
  bool bodyIntact(const std::vector<RigidBody>& bodies) const;
  // Birth position and launch axis (unit), and the velocity of the surface the particle leaves.
  void samplePlace(UniformRandom& random, const std::vector<RigidBody>& bodies, Vec3& position, Vec3& axis,
                   Vec3& surfaceVelocity) const;
  void spawn(std::size_t i, ParticleStore& store, UniformRandom& random, const std::vector<RigidBody>& bodies) const;

  EmitterDef def_;
  double pending_ = 0.0;        // particles due but not yet emitted, < 1 after each step
  bool burstDone_ = false;
  std::shared_ptr<const Mesh> mesh_;    // mesh surface: the body's mesh when the emitter was made
  std::vector<double> cumulativeArea_;  // ... and the running sum of its triangles' areas [m^2]
};

// A unit vector uniform over the cone of half-angle `spread` [rad] around the unit `axis`
// (cos theta uniform in [cos spread, 1], which is uniform over the spherical cap's area).
Vec3 sampleCone(const Vec3& axis, double spread, UniformRandom& random);

// The running sum of the mesh's triangle areas [m^2], in triangle order (the last is the surface
// area): what a mesh-surface emitter samples from, and what scenes check before making one.
std::vector<double> cumulativeTriangleAreas(const Mesh& mesh);

}  // namespace rbsim
