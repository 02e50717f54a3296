#pragma once
// Every tuning value of one particle system, with its default and unit (in the style of
// settings/settings.h). Seed 000's homework: "Build a particle system based either on F = ma or
// procedural simulation" (smoke, fire, water, wind, cloth, magnets, flocks); seed 004's cumulative
// submission asks for it beside the rigid bodies. Scenes fill it from "particles" blocks.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

// Particles are points: x' = v, v' = F / m (seed 000's homework, F = ma).
enum class ParticleIntegrator {
  ExplicitEuler,      // x += dt v_n, v += dt a(x_n, v_n): seed 000 "Forward Euler Update"; gains
                      // energy on springs
  SemiImplicitEuler,  // v += dt a(x_n, v_n), x += dt v_{n+1}: symplectic (Hairer, Lubich, Wanner,
                      // "Geometric Numerical Integration", VI.3), stable while omega dt < 2
};
const char* particleIntegratorName(ParticleIntegrator integrator);
bool parseParticleIntegrator(const std::string& name, ParticleIntegrator& out);
std::vector<std::string> particleIntegratorNames();

inline constexpr double kImmortal = std::numeric_limits<double>::infinity();  // lifetime [s]

enum class EmitterShape { Point, Disc, Box, MeshSurface };

// Emits `rate` particles per second (and `burst` at once when it starts) with initial conditions
// drawn uniformly from the ranges below by the system's seeded generator.
struct EmitterDef {
  EmitterShape shape = EmitterShape::Point;
  Vec3 position = Vec3::Zero();        // point, disc centre, box centre [m]
  Vec3 direction = Vec3::UnitY();      // unit: launch axis, and the disc's normal [1]
  double radius = 0.1;                 // disc radius [m]
  Vec3 halfExtents = Vec3::Constant(0.1);  // box half extents, world axes [m]
  std::size_t body = 0;                // mesh surface: the body whose surface emits (launch
                                       // along the face normal, plus the surface's velocity)
  double rate = 100.0;                 // [particles/s]
  std::size_t burst = 0;               // emitted in the first step of [start, end) [particles]
  double start = 0.0;                  // [s]
  double end = std::numeric_limits<double>::infinity();  // emits during [start, end) [s]
  double spreadDegrees = 15.0;         // half-angle of the launch cone around the axis [deg]
  double speedMin = 1.0, speedMax = 2.0;       // launch speed [m/s]
  double lifetimeMin = kImmortal, lifetimeMax = kImmortal;  // [s]
  double massMin = 0.01, massMax = 0.01;       // [kg]
  double sizeMin = 0.05, sizeMax = 0.05;       // drawn diameter [m]
  Vec3 color = Vec3::Ones();           // linear RGB at birth, each in [0, 1]
  double colorJitter = 0.0;            // each channel scaled by 1 + U(-j, j), clamped [1]
};

// Wind: an air velocity field w(x, t) = velocity + turbulence * noise(x / scale, t frequency),
// acting on particles through drag (F_drag uses v - w), as air does.
struct WindDef {
  Vec3 velocity = Vec3::Zero();  // mean wind [m/s]
  double turbulence = 0.0;       // amplitude of the noise field [m/s]
  double scale = 1.0;            // size of a gust [m]
  double frequency = 0.5;        // how fast the field changes [1/s]
};

// A point magnet: F = strength (a - x) / (|a - x|^2 + softening^2)^(3/2); strength > 0 attracts,
// < 0 repels. The softening keeps the force finite at the centre.
struct AttractorDef {
  Vec3 position = Vec3::Zero();  // [m]
  double strength = 1.0;         // [N m^2]
  double softening = 0.1;        // [m]
};

// Reynolds' boids (a procedural rule set) as forces on neighbours within `radius`.
struct FlockDef {
  bool enabled = false;
  double radius = 1.0;          // neighbourhood [m]
  double separation = 0.02;     // F = separation * sum d / |d|^2 over neighbours, d = x - x_j [N m]
  double alignment = 0.05;      // F = alignment * (mean neighbour v - v) [N s/m]
  double cohesion = 0.02;       // F = cohesion * (mean neighbour x - x) [N/m]
  double minSpeed = 0.0;        // speeds are clamped into [minSpeed, maxSpeed] after each step [m/s]
  double maxSpeed = std::numeric_limits<double>::infinity();  // [m/s]
};

// A rectangular cloth of nu x nv particles joined by springs: structural (grid neighbours), shear
// (diagonals) and bend (two apart); F = (k (|d| - L0) + c (v_b - v_a) . u) u on a, minus on b.
struct ClothDef {
  bool enabled = false;
  Vec3 origin = Vec3::Zero();        // corner of node (0, 0) [m]
  Vec3 edgeU = Vec3(1.0, 0.0, 0.0);  // from node (0, 0) to node (nu-1, 0) [m]
  Vec3 edgeV = Vec3(0.0, 0.0, 1.0);  // from node (0, 0) to node (0, nv-1) [m]
  int nu = 20, nv = 20;              // nodes along each edge [1]
  double mass = 0.5;                 // whole cloth, shared equally by the nodes [kg]
  double stiffness = 200.0;          // structural and shear springs, k [N/m]
  double bendStiffness = 20.0;       // springs two nodes apart [N/m]
  double damping = 0.05;             // along each spring, c [N s/m]
  std::vector<std::pair<int, int>> pinned;  // nodes (i, j) held in place (inverse mass 0)
  Vec3 color = Vec3(0.8, 0.2, 0.2);  // linear RGB of the shaded surface
};

struct ParticleCollisionDef {
  bool planes = true;        // against the World's planes
  bool bodies = true;        // against rigid bodies, as the convex set of their face planes
  double restitution = 0.3;  // normal velocity after = -restitution * before [1], in [0, 1]
  double friction = 0.3;     // Coulomb: |dv_t| <= friction |dv_n| [1] (seed 000 "Friction")
  double radius = 0.0;       // particles are kept this far outside surfaces [m]
};

struct ParticleSystemDef {
  std::string name = "particles";
  std::uint64_t seed = 1;                // of the generator drawing every initial condition
  std::size_t capacity = 10000;          // most particles alive at once; storage is made once
  ParticleIntegrator integrator = ParticleIntegrator::SemiImplicitEuler;
  int substeps = 1;                      // particle steps per World step, each dt / substeps [1]
  double gravityScale = 1.0;             // the World's g times this; < 0 rises (hot gas) [1]
  double dragLinear = 0.0;               // F = -k1 (v - w): terminal speed m g / k1 [N s/m]
  double dragQuadratic = 0.0;            // F = -k2 |v - w| (v - w) [N s^2/m^2]
  WindDef wind;
  std::vector<AttractorDef> attractors;
  FlockDef flock;
  ClothDef cloth;
  ParticleCollisionDef collision;
  std::vector<EmitterDef> emitters;
};

// Empty when the definition is usable; otherwise what is wrong, naming the field as in scenes.
std::string checkParticleSystemDef(const ParticleSystemDef& def, std::size_t bodyCount);

}  // namespace rbsim
