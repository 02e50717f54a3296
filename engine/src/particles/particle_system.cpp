#include "rbsim/particles/particle_system.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "math/fnv.h"
#include "particles/cloth.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim {

namespace {

const ParticleSystemDef& checked(const ParticleSystemDef& def, std::size_t bodyCount) {
  const std::string problem = checkParticleSystemDef(def, bodyCount);
  if (!problem.empty()) throw std::invalid_argument("particle system '" + def.name + "': " + problem);
  return def;
}

// The wind field's own seed, apart from the emitters' generator: wind does not change when an
// emitter is added.
constexpr std::uint64_t kWindSeedSalt = 0x5eed5eed5eed5eedull;

}  // namespace

ParticleSystem::ParticleSystem(const ParticleSystemDef& def, const std::vector<RigidBody>& bodies)
    : def_(checked(def, bodies.size())), store_(def_.capacity), random_(def_.seed) {
  for (const EmitterDef& e : def_.emitters) emitters_.emplace_back(e, bodies);
  if (def_.cloth.enabled) buildCloth(def_.cloth, store_, springs_, clothTriangles_);
  if (!springs_.empty() || def_.flock.enabled) force_.assign(def_.capacity, Vec3::Zero());
}

void ParticleSystem::step(double t, double dt, const Vec3& gravity, const std::vector<RigidBody>& bodies,
                          const std::vector<BodySolid>& shapes, const std::vector<Plane>& planes) {
  for (Emitter& emitter : emitters_) {
    const std::size_t before = store_.count();
    lost_ += emitter.emit(t, dt, store_, random_, bodies);
    emitted_ += store_.count() - before;
  }
  const double h = dt / def_.substeps;
  bool finite = true;
  for (int k = 0; k < def_.substeps; ++k) finite = substep(t + k * h, h, gravity, bodies, shapes, planes) && finite;
  // Every step when a velocity went NaN or infinite (a run may end before the next interval).
  if (++steps_ % kDivergenceCheckInterval == 0 || !finite) checkFinite(t, dt);
}

bool ParticleSystem::substep(double t, double h, const Vec3& gravity, const std::vector<RigidBody>& bodies,
                             const std::vector<BodySolid>& shapes, const std::vector<Plane>& planes) {
  ParticleStore& s = store_;
  const std::size_t n = s.count();
  const bool pairForces = !force_.empty();
  if (pairForces) {
    std::fill(force_.begin(), force_.begin() + static_cast<std::ptrdiff_t>(n), Vec3::Zero());
    addSpringForces(springs_, s, force_);
    if (def_.flock.enabled) addFlockingForces(def_.flock, s, force_);
  }
  // Everything below is decided once per substep, so the pass over the particles only tests
  // flags that never change inside it.
  const Vec3 g = def_.gravityScale * gravity;
  const double k1 = def_.dragLinear, k2 = def_.dragQuadratic;
  const bool drag = k1 != 0.0 || k2 != 0.0;
  const bool turbulent = def_.wind.turbulence != 0.0;
  const std::uint64_t windSeed = def_.seed ^ kWindSeedSalt;
  const bool semiImplicit = def_.integrator == ParticleIntegrator::SemiImplicitEuler;
  const ParticleCollisionDef& c = def_.collision;
  const bool hitPlanes = c.planes && !planes.empty();
  const bool hitBodies = c.bodies && !bodies.empty();
  const bool clampSpeed = def_.flock.enabled;
  // Locals, not members: the pass stores doubles, which the compiler must otherwise assume may
  // overwrite any double it reads through `this` (the wind, the planes) and reload them.
  const Vec3 meanWind = def_.wind.velocity;
  Vec3* const position = s.position.data();
  Vec3* const velocity = s.velocity.data();
  const double* const inverseMass = s.inverseMass.data();
  double* const age = s.age.data();
  const double* const lifetime = s.lifetime.data();
  bool anyExpired = false;
  // NaN or infinity in any velocity component makes this sum NaN or infinite: one add per
  // component, where a test of each particle inside the pass cost 17 % of the step.
  double velocitySum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = inverseMass[i];
    Vec3 x = position[i];
    Vec3 v = velocity[i];
    if (w > 0.0) {
      // a = F / m with F = m g + F_pairs + F_drag + F_magnets.
      Vec3 f = pairForces ? force_[i] : Vec3::Zero();
      if (drag) f += dragForce(v - (turbulent ? windVelocity(def_.wind, x, t, windSeed) : meanWind), k1, k2);
      for (const AttractorDef& a : def_.attractors) f += attractorForce(a, x);
      const Vec3 a = g + w * f;
      if (semiImplicit) {
        v += h * a;
        x += h * v;
      } else {
        x += h * v;
        v += h * a;
      }
      if (clampSpeed) {
        const double speed = v.norm();
        if (speed > def_.flock.maxSpeed) v *= def_.flock.maxSpeed / speed;
        else if (speed < def_.flock.minSpeed && speed > 0.0) v *= def_.flock.minSpeed / speed;
      }
      if (hitBodies) {
        for (std::size_t b = 0; b < bodies.size(); ++b) collideBody(x, v, bodies[b], shapes[b], c);
      }
      // Planes last: a body may push a particle, a plane never lets it below.
      if (hitPlanes) {
        for (const Plane& plane : planes) collidePlane(x, v, plane, c);
      }
      position[i] = x;
      velocity[i] = v;
      velocitySum += v.x() + v.y() + v.z();
    }
    age[i] += h;
    anyExpired |= age[i] >= lifetime[i];
  }
  if (anyExpired) s.removeExpired();
  return std::isfinite(velocitySum);
}

void ParticleSystem::checkFinite(double t, double dt) const {
  // NaN, infinity, or a speed beyond 1e154 m/s (where |v|^2 overflows): no scene gets there but
  // a diverging integrator. The velocity alone suffices: x stays finite while every v that moved
  // it was.
  std::size_t i = 0;
  while (i < store_.count() && std::isfinite(store_.velocity[i].squaredNorm())) ++i;
  if (i == store_.count()) return;
  std::ostringstream message;
  message << "particle system '" << def_.name << "': particle " << i << " left the finite numbers (or 1e154 m/s) within "
          << kDivergenceCheckInterval << " steps before t = " << t + dt << " s (integrator "
          << particleIntegratorName(def_.integrator) << ", substep h = " << dt / def_.substeps
          << " s).";
  // Springs are the usual cause with cloth; without them only the forces can drive a particle out.
  if (def_.cloth.enabled) {
    message << " Explicit Euler gains energy on springs; semi-implicit Euler needs omega h < 2 for the stiffest "
            << "spring: choose semi-implicit-euler, more substeps or softer springs.";
  } else {
    message << " Check its forces against the particle mass: wind, drag, gravity_scale, attractors and the "
            << "emitters' speeds.";
  }
  throw SimulationError(message.str());
}

std::uint64_t ParticleSystem::hashState(std::uint64_t hash) const {
  const auto mix = [&hash](double value) { hash = fnvMix(hash, value); };
  mix(static_cast<double>(store_.count()));
  for (std::size_t i = 0; i < store_.count(); ++i) {
    for (int k = 0; k < 3; ++k) mix(store_.position[i][k]);
    for (int k = 0; k < 3; ++k) mix(store_.velocity[i][k]);
    mix(store_.age[i]);
  }
  return hash;
}

}  // namespace rbsim
