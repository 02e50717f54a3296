#include "rbsim/particles/particle_def.h"

#include <cmath>
#include <string>

namespace rbsim {

const char* particleIntegratorName(ParticleIntegrator integrator) {
  switch (integrator) {
    case ParticleIntegrator::ExplicitEuler: return "explicit-euler";
    case ParticleIntegrator::SemiImplicitEuler: return "semi-implicit-euler";
  }
  return "unknown";
}

bool parseParticleIntegrator(const std::string& name, ParticleIntegrator& out) {
  for (ParticleIntegrator i : {ParticleIntegrator::ExplicitEuler, ParticleIntegrator::SemiImplicitEuler}) {
    if (name == particleIntegratorName(i)) {
      out = i;
      return true;
    }
  }
  return false;
}

std::vector<std::string> particleIntegratorNames() {
  return {particleIntegratorName(ParticleIntegrator::ExplicitEuler),
          particleIntegratorName(ParticleIntegrator::SemiImplicitEuler)};
}

namespace {

bool finiteAtLeast(double value, double low) { return std::isfinite(value) && value >= low; }
bool range(double lo, double hi, double low) { return finiteAtLeast(lo, low) && hi >= lo && !std::isnan(hi); }

std::string checkEmitter(const EmitterDef& e, std::size_t bodyCount) {
  if (e.shape == EmitterShape::MeshSurface && e.body >= bodyCount) return "body: names no body";
  if (!e.position.allFinite() || !e.direction.allFinite() || std::abs(e.direction.norm() - 1.0) > kUnitTolerance) {
    return "position, direction: expected a finite point and a unit direction";
  }
  if (!finiteAtLeast(e.radius, 0.0) || !(e.halfExtents.array() >= 0.0).all() || !e.halfExtents.allFinite()) {
    return "radius, extents: expected finite sizes >= 0 m";
  }
  if (!finiteAtLeast(e.rate, 0.0)) return "rate: expected a finite rate >= 0 particles/s";
  if (!finiteAtLeast(e.start, 0.0) || !(e.end > e.start)) return "start, end: expected 0 <= start < end s";
  if (!(e.spreadDegrees >= 0.0 && e.spreadDegrees <= 180.0)) return "spread_deg: expected an angle in [0, 180] degrees";
  if (!range(e.speedMin, e.speedMax, 0.0) || std::isinf(e.speedMax)) return "speed: expected 0 <= low <= high m/s";
  if (!(e.lifetimeMin > 0.0) || !(e.lifetimeMax >= e.lifetimeMin)) return "lifetime: expected 0 < low <= high s";
  if (!range(e.massMin, e.massMax, 0.0) || !(e.massMin > 0.0) || std::isinf(e.massMax)) return "mass: expected 0 < low <= high kg";
  if (!range(e.sizeMin, e.sizeMax, 0.0) || std::isinf(e.sizeMax)) return "size: expected 0 <= low <= high m";
  if (!e.color.allFinite() || !(e.color.array() >= 0.0).all() || !(e.color.array() <= 1.0).all()) {
    return "color: expected linear RGB, each in [0, 1]";
  }
  if (!finiteAtLeast(e.colorJitter, 0.0)) return "color_jitter: expected a finite fraction >= 0";
  return {};
}

}  // namespace

std::string checkParticleSystemDef(const ParticleSystemDef& d, std::size_t bodyCount) {
  if (d.capacity == 0) return "capacity: expected at least one particle";
  if (d.substeps < 1) return "substeps: expected at least 1";
  if (!std::isfinite(d.gravityScale)) return "gravity_scale: expected a finite number";
  if (!finiteAtLeast(d.dragLinear, 0.0)) return "drag_linear: expected a finite value >= 0 N s/m";
  if (!finiteAtLeast(d.dragQuadratic, 0.0)) return "drag_quadratic: expected a finite value >= 0 N s^2/m^2";
  if (!d.wind.velocity.allFinite() || !finiteAtLeast(d.wind.turbulence, 0.0) || !(d.wind.scale > 0.0) ||
      !std::isfinite(d.wind.scale) || !finiteAtLeast(d.wind.frequency, 0.0)) {
    return "wind: expected a finite velocity, turbulence >= 0 m/s, scale > 0 m, frequency >= 0 1/s";
  }
  for (const AttractorDef& a : d.attractors) {
    if (!a.position.allFinite() || !std::isfinite(a.strength) || !(a.softening > 0.0) || !std::isfinite(a.softening)) {
      return "attractors: expected a finite position and strength, softening > 0 m";
    }
  }
  const FlockDef& f = d.flock;
  if (f.enabled && (!(f.radius > 0.0) || !std::isfinite(f.radius) || !finiteAtLeast(f.separation, 0.0) ||
                    !finiteAtLeast(f.alignment, 0.0) || !finiteAtLeast(f.cohesion, 0.0) ||
                    !finiteAtLeast(f.minSpeed, 0.0) || !(f.maxSpeed >= f.minSpeed))) {
    return "flock: expected radius > 0 m, weights >= 0, 0 <= min_speed <= max_speed m/s";
  }
  const ParticleCollisionDef& c = d.collision;
  if (!(c.restitution >= 0.0 && c.restitution <= 1.0)) return "collision.restitution: expected a value in [0, 1]";
  if (!finiteAtLeast(c.friction, 0.0)) return "collision.friction: expected a finite value >= 0";
  if (!finiteAtLeast(c.radius, 0.0)) return "collision.radius: expected a finite distance >= 0 m";
  const ClothDef& cl = d.cloth;
  if (cl.enabled) {
    if (cl.nu < 2 || cl.nv < 2) return "cloth.resolution: expected at least 2 x 2 nodes";
    if (static_cast<std::size_t>(cl.nu) * static_cast<std::size_t>(cl.nv) > d.capacity) {
      return "capacity: expected room for the cloth's nu nv particles";
    }
    if (!(cl.mass > 0.0) || !std::isfinite(cl.mass) || !finiteAtLeast(cl.stiffness, 0.0) ||
        !finiteAtLeast(cl.bendStiffness, 0.0) || !finiteAtLeast(cl.damping, 0.0)) {
      return "cloth: expected mass > 0 kg, stiffness, bend_stiffness >= 0 N/m, damping >= 0 N s/m";
    }
    if (!cl.origin.allFinite() || !cl.edgeU.allFinite() || !cl.edgeV.allFinite() || !(cl.edgeU.cross(cl.edgeV).norm() > 0.0)) {
      return "cloth.edge_u, edge_v: expected two finite, non-parallel edges";
    }
    for (const auto& [i, j] : cl.pinned) {
      if (i < 0 || j < 0 || i >= cl.nu || j >= cl.nv) return "cloth.pinned: expected nodes [i, j] inside the grid";
    }
    // Springs index particles, and death reorders them: a cloth's system has no emitters.
    if (!d.emitters.empty()) return "emitters: a system with a cloth cannot have emitters";
  }
  for (std::size_t e = 0; e < d.emitters.size(); ++e) {
    const std::string p = checkEmitter(d.emitters[e], bodyCount);
    if (!p.empty()) return "emitters[" + std::to_string(e) + "]." + p;
  }
  return {};
}

}  // namespace rbsim
