// "particles": [{...}, ...]: one particle system per block. Every value is checked here with the
// JSON path in the message; checkParticleSystemDef backs it up when the World is built.
#include "scene/particle_parser.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "rbsim/io/input_error.h"
#include "rbsim/particles/emitter.h"
#include "rbsim/scene/json_fields.h"
#include "scene/body_parser.h"
#include "scene/input_ranges.h"

namespace rbsim::scene_detail {

namespace {

// More than this in one system is almost certainly a typo (1e6 particles take ~100 MB).
constexpr int kMaxParticleCapacity = 10'000'000;  // [particles]
constexpr int kMaxSubsteps = 1000;                // [1]
// An emitter faster than this fills the largest store (kMaxParticleCapacity) within 10 ms; the
// count due in a step must also stay a number a size_t holds.
constexpr double kMaxEmitterRate = 1e9;  // [particles/s]
// Particle work per World step over all systems: particle updates (each particle once per substep
// and once more per attractor, body and plane it is tested against) and spring evaluations. At 1
// to 5 ns each, the limit is ~0.1 s of computing per step, about 4 minutes per simulated 10 s at
// 240 steps/s.
constexpr double kMaxParticleWorkPerStep = 2e7;  // [updates or spring evaluations per step]
// Flock neighbour tests per World step over all systems: every boid against every other that can
// be alive at once (any may come within `radius`). A test is a distance and a compare, ~1 ns: the
// limit is ~0.4 s per step; a flock of 1e5 (1e10 tests) would take minutes per step.
constexpr double kMaxFlockTestsPerStep = 4e8;  // [pair tests per step]
// Birth sizes are stored as float (for the renderer).
constexpr double kMaxFloatSize = 3.4e38;  // [m], just under FLT_MAX

double atLeast(const JsonObject& o, const char* key, double fallback, double low, const char* unit) {
  const double d = o.number(key, fallback);
  if (!(d >= low)) o.fail(key, "expected a value >= " + formatNumber(low) + " " + unit + ", got " + formatNumber(d));
  return d;
}

double fraction(const JsonObject& o, const char* key, double fallback) {
  const double d = o.number(key, fallback);
  if (!(d >= 0.0 && d <= 1.0)) o.fail(key, "expected a value in [0, 1], got " + formatNumber(d));
  return d;
}

// A number (low = high) or [low, high] with minimum <= low <= high; `positive` excludes 0.
void range(const JsonObject& o, const char* key, double& lo, double& hi, bool positive, const char* unit) {
  if (!o.has(key)) return;
  const nlohmann::json& r = o.raw(key);
  const std::string expected = std::string("expected a number or [low, high] with ") + (positive ? "0 < " : "0 <= ") +
                               "low <= high, in " + unit;
  if (r.is_number()) {
    lo = hi = r.get<double>();
  } else if (r.is_array() && r.size() == 2 && r[0].is_number() && r[1].is_number()) {
    lo = r[0].get<double>();
    hi = r[1].get<double>();
  } else {
    o.fail(key, expected);
  }
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi >= lo) || lo < 0.0 || (positive && !(lo > 0.0))) o.fail(key, expected);
}

Vec3 unitDirection(const JsonObject& o, const char* key, const Vec3& fallback) {
  const Vec3 d = o.vec3(key, fallback);
  if (!(d.norm() > 0.0)) o.fail(key, "expected a non-zero direction");
  return d.normalized();
}

Vec3 color(const JsonObject& o, const char* key, const Vec3& fallback) {
  const Vec3 c = o.vec3(key, fallback);
  if (!(c.array() >= 0.0).all() || !(c.array() <= 1.0).all()) o.fail(key, "expected linear RGB, each in [0, 1]");
  return c;
}

// What the emitter derives from its numbers, checked here against the field it came from.
void checkEmitterDerived(const JsonObject& e, const EmitterDef& d, const Scene& scene) {
  if (d.rate > kMaxEmitterRate) {
    e.fail("rate", "expected at most " + formatNumber(kMaxEmitterRate) + " particles/s, got " + formatNumber(d.rate));
  }
  const double reach = d.shape == EmitterShape::Disc ? d.radius : d.shape == EmitterShape::Box ? d.halfExtents.maxCoeff() : 0.0;
  if (!std::isfinite(d.position.cwiseAbs().maxCoeff() + reach)) {
    e.fail(d.shape == EmitterShape::Disc ? "radius" : "half_extents",
           "the birth points (position +- the emitter's size) overflow; expected finite sums");
  }
  if (!std::isfinite(1.0 / d.massMin)) {
    e.fail("mass", "1 / the lowest mass (" + formatNumber(d.massMin) + " kg) overflows; expected a mass whose inverse is finite");
  }
  if (d.sizeMax > kMaxFloatSize) e.fail("size", "expected sizes at most " + formatNumber(kMaxFloatSize) + " m (stored as float)");
  if (d.shape == EmitterShape::MeshSurface) {
    const std::vector<double> areas = cumulativeTriangleAreas(*scene.bodies[d.body].mesh);
    const double area = areas.empty() ? 0.0 : areas.back();
    if (!(area > 0.0) || !std::isfinite(area)) {
      e.fail("body", "the body's surface area is " + formatNumber(area) + " m^2; expected a finite area > 0 to emit from");
    }
  }
}

EmitterDef parseEmitter(const JsonObject& e, const Scene& scene) {
  EmitterDef d;
  const std::string type = e.requiredString("type");
  if (type == "point") d.shape = EmitterShape::Point;
  else if (type == "disc") d.shape = EmitterShape::Disc;
  else if (type == "box") d.shape = EmitterShape::Box;
  else if (type == "mesh") d.shape = EmitterShape::MeshSurface;
  else e.fail("type", "expected \"point\", \"disc\", \"box\" or \"mesh\", got \"" + type + "\"");
  if (d.shape == EmitterShape::MeshSurface) {
    if (!e.has("body")) e.fail("body", "missing; a mesh emitter names the body whose surface emits");
    d.body = findBody(scene.bodies, e, "body");
  } else if (e.has("body")) {
    e.fail("body", "only a \"mesh\" emitter has a body");
  }
  d.position = e.boundedVec3("position", d.position, kMaxCoordinate, "m", "the farthest a scene reaches");
  d.direction = unitDirection(e, "direction", d.direction);
  d.radius = atLeast(e, "radius", d.radius, 0.0, "m");
  if (e.has("half_extents")) {
    d.halfExtents = e.boundedVec3("half_extents", d.halfExtents, kMaxCoordinate, "m", "the farthest a scene reaches");
    if (!(d.halfExtents.array() >= 0.0).all()) e.fail("half_extents", "expected every component >= 0 m");
  }
  d.rate = atLeast(e, "rate", d.rate, 0.0, "particles/s");
  if (e.has("burst")) {
    const nlohmann::json& b = e.raw("burst");
    if (!b.is_number_integer() || b.get<long long>() < 0 || b.get<long long>() > kMaxParticleCapacity) {
      e.fail("burst", "expected an integer in [0, " + std::to_string(kMaxParticleCapacity) + "] particles");
    }
    d.burst = static_cast<std::size_t>(b.get<long long>());
  }
  d.start = atLeast(e, "start", d.start, 0.0, "s");
  if (e.has("end")) {
    d.end = e.number("end", 0.0);
    if (!(d.end > d.start)) e.fail("end", "expected a time after \"start\"");
  }
  d.spreadDegrees = e.number("spread_deg", d.spreadDegrees);
  if (!(d.spreadDegrees >= 0.0 && d.spreadDegrees <= 180.0)) e.fail("spread_deg", "expected an angle in [0, 180] degrees");
  range(e, "speed", d.speedMin, d.speedMax, false, "m/s");
  if (d.speedMax > kMaxSpeed) e.fail("speed", "expected speeds below the speed of light, 299792458 m/s");
  range(e, "lifetime", d.lifetimeMin, d.lifetimeMax, true, "s");
  range(e, "mass", d.massMin, d.massMax, true, "kg");
  range(e, "size", d.sizeMin, d.sizeMax, false, "m");
  d.color = color(e, "color", d.color);
  d.colorJitter = atLeast(e, "color_jitter", d.colorJitter, 0.0, "(fraction)");
  checkEmitterDerived(e, d, scene);
  return d;
}

void parseCloth(const JsonObject& c, ClothDef& cloth) {
  cloth.enabled = true;
  cloth.origin = c.boundedVec3("origin", cloth.origin, kMaxCoordinate, "m", "the farthest a scene reaches");
  cloth.edgeU = c.boundedVec3("edge_u", cloth.edgeU, kMaxCoordinate, "m", "the farthest a scene reaches");
  cloth.edgeV = c.boundedVec3("edge_v", cloth.edgeV, kMaxCoordinate, "m", "the farthest a scene reaches");
  if (!(cloth.edgeU.cross(cloth.edgeV).stableNorm() > 0.0)) {
    c.fail("edge_v", "expected an edge neither zero nor parallel to \"edge_u\" (nor so short that |edge_u x edge_v| underflows to 0)");
  }
  if (c.has("resolution")) {
    const nlohmann::json& r = c.raw("resolution");
    if (!r.is_array() || r.size() != 2 || !r[0].is_number_integer() || !r[1].is_number_integer() || r[0].get<long long>() < 2 ||
        r[1].get<long long>() < 2 || r[0].get<long long>() > 1000 || r[1].get<long long>() > 1000) {
      c.fail("resolution", "expected [nu, nv] nodes, each an integer in [2, 1000]");
    }
    cloth.nu = r[0].get<int>();
    cloth.nv = r[1].get<int>();
  }
  cloth.mass = c.positiveNumber("mass", cloth.mass);
  cloth.stiffness = atLeast(c, "stiffness", cloth.stiffness, 0.0, "N/m");
  cloth.bendStiffness = atLeast(c, "bend_stiffness", cloth.bendStiffness, 0.0, "N/m");
  cloth.damping = atLeast(c, "damping", cloth.damping, 0.0, "N s/m");
  cloth.color = color(c, "color", cloth.color);
  const double area = cloth.edgeU.cross(cloth.edgeV).stableNorm();
  if (!std::isfinite(area) || !(cloth.origin + cloth.edgeU + cloth.edgeV).allFinite() ||
      !(cloth.origin.cwiseAbs() + cloth.edgeU.cwiseAbs() + cloth.edgeV.cwiseAbs()).allFinite()) {
    c.fail("edge_u", "the cloth's corners or its area |edge_u x edge_v| (" + formatNumber(area) +
                         " m^2) overflow; expected finite values");
  }
  const double nodeMass = cloth.mass / (static_cast<double>(cloth.nu) * cloth.nv);
  if (!(nodeMass > 0.0) || !std::isfinite(1.0 / nodeMass)) {
    c.fail("mass", "a node's mass mass / (nu nv) = " + formatNumber(nodeMass) + " kg; expected one whose inverse is finite");
  }
  const double stiffest = std::max(cloth.stiffness, cloth.bendStiffness);
  if (!std::isfinite(stiffest / nodeMass) || !std::isfinite(cloth.damping / nodeMass)) {
    c.fail(cloth.stiffness >= cloth.bendStiffness ? "stiffness" : "bend_stiffness",
           "k / m for a node of " + formatNumber(nodeMass) + " kg (k = " + formatNumber(stiffest) + " N/m, damping " +
               formatNumber(cloth.damping) + " N s/m) overflows; expected finite spring rates");
  }
  if (c.has("pinned")) {
    const nlohmann::json& p = c.raw("pinned");
    const auto bad = [&] { c.fail("pinned", "expected [[i, j], ...], nodes inside the [nu, nv] grid"); };
    if (!p.is_array()) bad();
    for (const nlohmann::json& node : p) {
      if (!node.is_array() || node.size() != 2 || !node[0].is_number_integer() || !node[1].is_number_integer()) bad();
      const long long i = node[0].get<long long>(), j = node[1].get<long long>();
      if (i < 0 || j < 0 || i >= cloth.nu || j >= cloth.nv) bad();
      cloth.pinned.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
  }
}

ParticleLook parseLook(const JsonObject& l) {
  ParticleLook look;
  const std::string blend = l.string("blend", "alpha");
  if (blend == "additive") look.blend = ParticleLook::Blend::Additive;
  else if (blend != "alpha") l.fail("blend", "expected \"additive\" or \"alpha\", got \"" + blend + "\"");
  look.hasColorEnd = l.has("color_end");
  look.colorEnd = color(l, "color_end", look.colorEnd);
  look.alphaStart = fraction(l, "alpha_start", look.alphaStart);
  look.alphaEnd = fraction(l, "alpha_end", look.alphaEnd);
  look.sizeEndScale = atLeast(l, "size_end_scale", look.sizeEndScale, 0.0, "(ratio)");
  return look;
}

ParticleSystemDef parseSystem(const JsonObject& p, std::size_t index, const Scene& scene) {
  ParticleSystemDef d;
  d.name = p.string("name", "particles_" + std::to_string(index));
  d.seed = static_cast<std::uint64_t>(p.positiveInt("seed", 1));
  const int capacity = p.positiveInt("capacity", static_cast<int>(d.capacity));
  if (capacity > kMaxParticleCapacity) p.fail("capacity", "expected at most " + std::to_string(kMaxParticleCapacity) + " particles");
  d.capacity = static_cast<std::size_t>(capacity);
  d.integrator = scene.particleIntegrator;
  const std::string integrator = p.string("integrator", particleIntegratorName(d.integrator));
  if (!parseParticleIntegrator(integrator, d.integrator)) {
    p.fail("integrator", "unknown particle integrator \"" + integrator + "\"; expected explicit-euler or semi-implicit-euler");
  }
  d.substeps = p.positiveInt("substeps", d.substeps);
  if (d.substeps > kMaxSubsteps) p.fail("substeps", "expected at most " + std::to_string(kMaxSubsteps));
  d.gravityScale = p.number("gravity_scale", d.gravityScale);
  if (!std::isfinite(d.gravityScale * scene.settings.gravity.stableNorm())) {
    p.fail("gravity_scale", "gravity_scale x |world.gravity| = " + formatNumber(d.gravityScale) + " x " +
                                formatNumber(scene.settings.gravity.stableNorm()) + " m/s^2 overflows; expected a finite product");
  }
  d.dragLinear = atLeast(p, "drag_linear", d.dragLinear, 0.0, "N s/m");
  d.dragQuadratic = atLeast(p, "drag_quadratic", d.dragQuadratic, 0.0, "N s^2/m^2");
  if (p.has("wind")) {
    const JsonObject w = p.object("wind", {"velocity", "turbulence", "scale", "frequency"});
    d.wind.velocity = w.boundedVec3("velocity", d.wind.velocity, kMaxSpeed, "m/s", "the speed of light");
    d.wind.turbulence = atLeast(w, "turbulence", d.wind.turbulence, 0.0, "m/s");
    d.wind.scale = w.positiveNumber("scale", d.wind.scale);
    d.wind.frequency = atLeast(w, "frequency", d.wind.frequency, 0.0, "1/s");
    if (!std::isfinite(d.wind.velocity.cwiseAbs().maxCoeff() + d.wind.turbulence)) {
      w.fail("turbulence", "the wind's speed, velocity + turbulence, overflows; expected a finite sum");
    }
    if (!std::isfinite(1.0 / d.wind.scale)) {
      w.fail("scale", "1 / scale overflows (scale " + formatNumber(d.wind.scale) + " m); expected a gust size whose inverse is finite");
    }
  }
  for (const JsonObject& a : p.objectArray("attractors", {"position", "strength", "softening"})) {
    AttractorDef attractor;
    attractor.position = a.boundedVec3("position", attractor.position, kMaxCoordinate, "m", "the farthest a scene reaches");
    attractor.strength = a.number("strength", attractor.strength);
    attractor.softening = a.positiveNumber("softening", attractor.softening);
    // The force's largest magnitude, at |a - x| = softening / sqrt(2), is ~0.385 strength / softening^2.
    const double peak = std::abs(attractor.strength) / (attractor.softening * attractor.softening);
    if (!std::isfinite(peak)) {
      a.fail("softening", "strength / softening^2 = " + formatNumber(peak) + " N overflows; expected a finite peak force");
    }
    d.attractors.push_back(attractor);
  }
  if (p.has("flock")) {
    const JsonObject f = p.object("flock", {"radius", "separation", "alignment", "cohesion", "min_speed", "max_speed"});
    d.flock.enabled = true;
    d.flock.radius = f.positiveNumber("radius", d.flock.radius);
    d.flock.separation = atLeast(f, "separation", d.flock.separation, 0.0, "N m");
    d.flock.alignment = atLeast(f, "alignment", d.flock.alignment, 0.0, "N s/m");
    d.flock.cohesion = atLeast(f, "cohesion", d.flock.cohesion, 0.0, "N/m");
    d.flock.minSpeed = atLeast(f, "min_speed", d.flock.minSpeed, 0.0, "m/s");
    if (f.has("max_speed")) d.flock.maxSpeed = f.positiveNumber("max_speed", 1.0);
    if (d.flock.maxSpeed < d.flock.minSpeed) f.fail("max_speed", "expected a speed >= \"min_speed\"");
  }
  if (p.has("collision")) {
    const JsonObject c = p.object("collision", {"planes", "bodies", "restitution", "friction", "radius"});
    d.collision.planes = c.boolean("planes", d.collision.planes);
    d.collision.bodies = c.boolean("bodies", d.collision.bodies);
    d.collision.restitution = fraction(c, "restitution", d.collision.restitution);
    d.collision.friction = atLeast(c, "friction", d.collision.friction, 0.0, "(coefficient)");
    d.collision.radius = atLeast(c, "radius", d.collision.radius, 0.0, "m");
  }
  if (p.has("cloth")) {
    parseCloth(p.object("cloth", {"origin", "edge_u", "edge_v", "resolution", "mass", "stiffness", "bend_stiffness",
                                  "damping", "pinned", "color"}),
               d.cloth);
    if (static_cast<std::size_t>(d.cloth.nu) * static_cast<std::size_t>(d.cloth.nv) > d.capacity) {
      if (p.has("capacity")) p.fail("capacity", "expected room for the cloth's nu nv particles");
      d.capacity = static_cast<std::size_t>(d.cloth.nu) * static_cast<std::size_t>(d.cloth.nv);
    }
    if (p.has("emitters")) p.fail("emitters", "a system with a cloth cannot have emitters (springs index its particles)");
  }
  for (const JsonObject& e :
       p.objectArray("emitters", {"type", "position", "direction", "radius", "half_extents", "body", "rate", "burst", "start",
                                  "end", "spread_deg", "speed", "lifetime", "mass", "size", "color", "color_jitter"})) {
    d.emitters.push_back(parseEmitter(e, scene));
  }
  if (d.emitters.empty() && !d.cloth.enabled) p.fail("emitters", "missing; a particle system needs an emitter or a cloth");
  return d;
}

// The most particles of the system alive at once: its capacity, or fewer when its emitters cannot
// fill it (bursts, plus rate times the lifetime or the emitting window, whichever is shorter).
double mostAlive(const ParticleSystemDef& d) {
  double alive = d.cloth.enabled ? static_cast<double>(d.cloth.nu) * d.cloth.nv : 0.0;
  for (const EmitterDef& e : d.emitters) {
    const double stream = e.rate > 0.0 ? e.rate * std::min(e.lifetimeMax, e.end - e.start) + 1.0 : 0.0;
    alive += static_cast<double>(e.burst) + stream;
  }
  return std::min(static_cast<double>(d.capacity), alive);  // an immortal stream gives infinity: the capacity
}

// The work of one World step of the system: updates and spring evaluations, and flock neighbour
// tests apart; what they are, in words.
void workPerStep(const ParticleSystemDef& d, const Scene& scene, double& work, double& pairs, std::string& what) {
  const double n = static_cast<double>(d.capacity), substeps = d.substeps;
  double tests = 1.0 + static_cast<double>(d.attractors.size());
  if (d.collision.bodies) tests += scene.mostBodiesAtOnce();  // ragdoll bones and spawned bodies too
  if (d.collision.planes) tests += static_cast<double>(scene.planes.size());
  const double updates = n * tests * substeps;
  const double springs = d.cloth.enabled ? 6.0 * d.cloth.nu * d.cloth.nv * substeps : 0.0;
  const double alive = mostAlive(d);
  pairs = d.flock.enabled ? alive * alive * substeps : 0.0;
  std::ostringstream out;
  out << "capacity " << d.capacity << " x " << d.substeps << " substeps: " << formatNumber(updates) << " particle updates";
  if (d.cloth.enabled) out << ", " << formatNumber(springs) << " spring evaluations";
  if (d.flock.enabled) {
    out << ", and " << formatNumber(pairs) << " flock neighbour tests (" << formatNumber(alive)
        << " boids alive at most, each against every other)";
  }
  what = out.str();
  work = updates + springs;
}

}  // namespace

void parseParticleSystems(const JsonObject& root, Scene& scene) {
  const std::vector<JsonObject> systems = root.objectArray(
      "particles", {"name", "seed", "capacity", "integrator", "substeps", "gravity_scale", "drag_linear", "drag_quadratic",
                    "wind", "attractors", "flock", "collision", "cloth", "emitters", "look"});
  double work = 0.0, pairs = 0.0;  // per World step, over the systems so far
  for (std::size_t i = 0; i < systems.size(); ++i) {
    const JsonObject& p = systems[i];
    ParticleSystemDef def = parseSystem(p, i, scene);
    const std::string problem = checkParticleSystemDef(def, scene.bodies.size());
    if (!problem.empty()) throw InputError(scene.file, p.path(), problem);
    std::string what;
    double systemWork = 0.0, systemPairs = 0.0;
    workPerStep(def, scene, systemWork, systemPairs, what);
    work += systemWork;
    pairs += systemPairs;
    if (work > kMaxParticleWorkPerStep || pairs > kMaxFlockTestsPerStep) {
      const bool flock = pairs > kMaxFlockTestsPerStep;
      std::ostringstream problem;
      problem << what << " per World step; with the systems before it, " << formatNumber(flock ? pairs : work)
              << (flock ? " neighbour tests" : " updates") << " per step, and the limit is "
              << formatNumber(flock ? kMaxFlockTestsPerStep : kMaxParticleWorkPerStep)
              << " per step: use a smaller capacity, fewer substeps" << (flock ? " or a smaller flock" : "");
      p.fail(flock ? "flock" : def.cloth.enabled ? "cloth" : "capacity", problem.str());
    }
    scene.particleSystems.push_back(std::move(def));
    scene.particleLooks.push_back(p.has("look") ? parseLook(p.object("look", {"blend", "color_end", "alpha_start", "alpha_end",
                                                                              "size_end_scale"}))
                                                : ParticleLook{});
  }
}

}  // namespace rbsim::scene_detail
