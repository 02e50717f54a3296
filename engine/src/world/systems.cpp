// The systems beside the rigid bodies, each behind the StepListener seam (world/systems.h).
#include "rbsim/world/systems.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "math/fnv.h"
#include "rbsim/integrate/simulation_error.h"
#include "soft/soft_contact.h"

namespace rbsim {

namespace {

// Seed 000's particle systems: bodies move particles, particles never push bodies.
class ParticleSystems final : public StepListener {
 public:
  std::vector<ParticleSystem> systems;

  std::unique_ptr<StepListener> clone() const override { return std::make_unique<ParticleSystems>(*this); }
  bool idle() const override { return systems.empty(); }
  void step(const StepContext& c) override {
    for (ParticleSystem& system : systems) {
      system.step(c.time, c.settings.timeStep, c.settings.gravity, c.bodies, c.shapes, c.planes);
    }
  }
  void bodyRemoved(std::size_t removed, std::size_t from, std::size_t to) override {
    for (ParticleSystem& system : systems) system.bodyRemoved(removed, from, to);
  }
  std::uint64_t hashState(std::uint64_t hash) const override {
    for (const ParticleSystem& system : systems) hash = system.hashState(hash);
    return hash;
  }
};

// FEM soft bodies: elastic forces, integrate, nodes against planes and rigid bodies (both ways).
class SoftBodies final : public StepListener {
 public:
  std::vector<SoftBody> bodies;

  std::unique_ptr<StepListener> clone() const override { return std::make_unique<SoftBodies>(*this); }
  bool idle() const override { return bodies.empty(); }
  void step(const StepContext& c) override {
    for (SoftBody& soft : bodies) {
      try {
        soft.step(c.settings.timeStep, c.settings.gravity, c.planes, c.planeMaterials);
      } catch (const std::domain_error& e) {  // non-finite nodes, or an inverted neo-Hookean element
        const std::string what = e.what();
        const std::string who = what.find(soft.name()) == std::string::npos ? "soft body '" + soft.name() + "': " : "";
        throw SimulationError("step " + std::to_string(c.stepCount) + ": " + who + what);
      }
      if (c.settings.detectCollisions) collideSoftWithRigid(soft, c.bodies, c.shapes, c.bodyMaterials, soft.material());
    }
  }
  std::uint64_t hashState(std::uint64_t hash) const override {
    for (const SoftBody& soft : bodies) {
      for (const Vec3& x : soft.positions()) {
        for (int i = 0; i < 3; ++i) hash = fnvMix(hash, x[i]);
      }
      for (const Vec3& v : soft.velocities()) {
        for (int i = 0; i < 3; ++i) hash = fnvMix(hash, v[i]);
      }
    }
    return hash;
  }
};

// Seed 002's 2D rigid bodies, in their own world of polygons and lines.
class PlanarSystem final : public StepListener {
 public:
  explicit PlanarSystem(const PlanarSettings& settings) : world(settings) {}
  PlanarWorld world;

  std::unique_ptr<StepListener> clone() const override { return std::make_unique<PlanarSystem>(*this); }
  bool idle() const override { return false; }
  void step(const StepContext&) override { world.step(); }
  std::uint64_t hashState(std::uint64_t hash) const override {
    for (const PlanarBody& b : world.bodies()) {
      const PlanarState& s = b.state();
      for (double value : {s.position.x(), s.position.y(), s.angle, s.linearMomentum.x(), s.linearMomentum.y(), s.angularMomentum}) {
        hash = fnvMix(hash, value);
      }
    }
    return hash;
  }
};

template <typename T>
T* find(const World& world) {
  for (const std::unique_ptr<StepListener>& listener : world.stepListeners()) {
    if (auto* system = dynamic_cast<T*>(listener.get())) return system;
  }
  return nullptr;
}

template <typename T>
T& findOrAdd(World& world) {
  if (T* system = find<T>(world)) return *system;
  return static_cast<T&>(world.addStepListener(std::make_unique<T>()));
}

}  // namespace

std::size_t addParticleSystem(World& world, const ParticleSystemDef& def) {
  ParticleSystem system(def, world.bodies());  // throws before the World changes
  std::vector<ParticleSystem>& systems = findOrAdd<ParticleSystems>(world).systems;
  systems.push_back(std::move(system));
  return systems.size() - 1;
}

const std::vector<ParticleSystem>& particleSystems(const World& world) {
  static const std::vector<ParticleSystem> none;
  const ParticleSystems* systems = find<ParticleSystems>(world);
  return systems ? systems->systems : none;
}

std::vector<ParticleSystem>& particleSystems(World& world) { return findOrAdd<ParticleSystems>(world).systems; }

std::size_t addSoftBody(World& world, const SoftBodyDef& def) {
  SoftBody soft(def);
  std::vector<SoftBody>& bodies = findOrAdd<SoftBodies>(world).bodies;
  bodies.push_back(std::move(soft));
  return bodies.size() - 1;
}

const std::vector<SoftBody>& softBodies(const World& world) {
  static const std::vector<SoftBody> none;
  const SoftBodies* soft = find<SoftBodies>(world);
  return soft ? soft->bodies : none;
}

std::vector<SoftBody>& softBodies(World& world) { return findOrAdd<SoftBodies>(world).bodies; }

void setPlanarWorld(World& world, const PlanarWorld& planar) {
  PlanarSettings settings = planar.settings();
  settings.timeStep = world.settings().timeStep;
  settings.gravity = Vec2(world.settings().gravity.x(), world.settings().gravity.y());
  auto system = std::make_unique<PlanarSystem>(settings);
  for (const PlanarBody& body : planar.bodies()) system->world.addBody(body);
  for (const PlanarLine& line : planar.lines()) system->world.addLine(line);
  if (PlanarSystem* old = find<PlanarSystem>(world)) {
    old->world = std::move(system->world);
    return;
  }
  world.addStepListener(std::move(system));
}

const PlanarWorld* planarWorld(const World& world) {
  const PlanarSystem* system = find<PlanarSystem>(world);
  return system ? &system->world : nullptr;
}

PlanarWorld* planarWorld(World& world) {
  PlanarSystem* system = find<PlanarSystem>(world);
  return system ? &system->world : nullptr;
}

}  // namespace rbsim
