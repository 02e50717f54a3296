#pragma once
// Every tuning value of a World, with its default and unit (as qu3e's q3Settings.h and Jolt's
// PhysicsSettings). Scenes and `--set world.KEY=VALUE` override them.
#include <string>

#include "rbsim/integrate/integrator.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/math/types.h"

namespace rbsim {

// A step longer than this is rejected as absurd: at 0.1 s a body falling for one second moves
// ~1 m per step, beyond anything a rigid-body scene at human scale resolves.
inline constexpr double kMaxTimeStep = 0.1;  // [s]
// A step shorter than this is rejected too: one simulated second would take over a million steps,
// and the increments dt v fall towards the rounding of positions of order 1 m.
inline constexpr double kMinTimeStep = 1e-6;  // [s]
// More substeps than this buy nothing a smaller dt would not, and each costs a full solve.
inline constexpr int kMaxSubsteps = 64;  // [substeps]
// PGS sweeps per step: a hundred times the defaults of Box2D v2 (8) and Bullet (10). Each sweep
// visits every contact point, so 1e9 sweeps of one box on a plane already take minutes a step.
inline constexpr int kMaxSolverIterations = 1000;  // [sweeps]
// Worker threads of one World: far above any machine's cores today; more threads than cores still
// work (they share the cores), a thousand would only cost their stacks and their start.
inline constexpr int kMaxThreads = 256;  // [threads]

// The machine's cores (std::thread::hardware_concurrency), 1 when it cannot tell: Settings::threads'
// default.
int machineThreads();

struct Settings {
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);      // [m/s^2], y is up
  double timeStep = 1.0 / 240.0;             // dt [s], in [kMinTimeStep, kMaxTimeStep]
  // The most accurate at every cost on the error-against-time front (REPORT section 6,
  // docs/integrators.md).
  Integrator integrator = Integrator::Exact;
  InertiaMethod inertia = InertiaMethod::Exact;  // default for bodies that do not choose
  // Seed 004 "Drift correction": euler-matrix re-orthonormalises R after each R += dt omega* R.
  // false keeps the raw matrix, so the drift the seed warns of (the body shears and grows) shows;
  // only euler-matrix reads it. A contact or joint solve works on the body's nearest rotation, and
  // R restarts from it there.
  bool driftCorrection = true;

  // Sleeping (Box2D's b2_linearSleepTolerance, b2_angularSleepTolerance, b2_timeToSleep): a body
  // slower than both speeds for timeToSleep is put to sleep (its momenta set to zero) and is not
  // integrated until a pose event, a scripted force or a contact wakes it. Under gravity g a
  // free body stays below sleepLinearSpeed for at most 2 sleepLinearSpeed / |g| (2 ms at 9.81),
  // far less than timeToSleep, so free flight never sleeps.
  bool allowSleep = true;
  double sleepLinearSpeed = 0.01;    // [m/s]
  double sleepAngularSpeed = 0.035;  // [rad/s], 2 degrees per second
  double timeToSleep = 0.5;          // [s]

  // Collision detection (engine/collision, engine/src/world/collision_pipeline.h). false: bodies
  // pass through each other and through planes unseen, and the three collision stages never run
  // (scenes of free flight, and the throughput benchmark of the unconstrained step).
  bool detectCollisions = true;
  enum class BroadPhaseMethod { SweepAndPrune, BruteForce };
  BroadPhaseMethod broadPhase = BroadPhaseMethod::SweepAndPrune;  // brute force: the O(n^2) reference
  // Pairs closer than this get speculative contacts (depth < 0), and AABBs are inflated by it, so
  // a contact is known a step before the surfaces meet (Box2D's speculative distance is 4 cm).
  double contactMargin = 0.01;  // [m]
  // Contact recycling (Box3D's, src/physics_world.c; soft step only): a pair of polyhedra whose
  // relative pose has moved less than this since its manifold was computed keeps that manifold's
  // normal and lever arms, and only brings its separations up to date, as the soft step's
  // substeps do within a step (world/contact_recycling.h). A column of 20 cubes at 30 Hz on 4
  // substeps stands with it and buckles without it, in Box3D as in rbsim (docs/speed.md).
  // kAutoRecycleDistance (the scene's "auto") takes kRecycleGravityFactor |g| h^2 for the substep
  // h (recycleDistance below); 0 collides every pair afresh every step.
  double contactRecycleDistance = -1.0;  // [m]; kAutoRecycleDistance
  // Continuous collision: a body whose points may move more than ccdMotionFraction of its
  // thinnest extent in one step is swept, and stopped at its time of impact instead of passing
  // through a plane or a body (engine/src/world/continuous_collision.h).
  bool continuousCollision = true;
  double ccdMotionFraction = 0.25;  // [1]
  // Seed 004's debugging tip (after Ericson): keep the last queryLogCapacity narrow-phase queries
  // for dumping (CollisionPipeline::queryLog). Off unless asked for: recording every query costs
  // the narrow phase a summary and a copy per pair, for a log nobody reads in a normal run.
  bool logQueries = false;
  std::size_t queryLogCapacity = 256;  // [records]

  // Contact response. false: contacts are detected and reported but nothing acts on them, so
  // bodies pass through each other (the narrow phase on its own).
  bool respondToContacts = true;
  // The contact solver, behind one seam (engine/src/dynamics/contact_solver.h). SoftStep
  // (soft_step_solver.h, the default): substeps of soft contact constraints with relaxation
  // (Catto, "Solver2D", 2024; Box2D v3). Pgs (pgs_solver.h): projected Gauss-Seidel with split
  // impulses, kept as the reference. Lcp (lcp_solver.h, issue 55): seed 001's resting contact as
  // an exact linear complementarity problem per island, by Dantzig's principal pivoting, for small
  // scenes (kMaxLcpRows contact points an island), with PGS's friction cone beside it.
  enum class ContactSolverMethod { SoftStep, Pgs, Lcp };
  ContactSolverMethod solver = ContactSolverMethod::SoftStep;
  // Soft step: substeps per step, each one solve sweep with bias and one relax sweep without.
  // Box2D v3 runs 4 with 30 Hz contacts; at dt = 1/60 s that sinks a column of 20 unit boxes
  // 2.8 cm into itself (a spring of f Hz sags F / (m omega^2) per contact) and topples one of 40.
  // 8 substeps carry contacts of 120 Hz: 7 mm lost by 20 boxes, 40 stand (bench/contact_scenes);
  // but Box3D's 100-row pyramid (bench/box3d_scenes, 10 s at 1/60 s) never rests at 120 Hz on 8
  // (0.77 m/s at the end), rests sinking 17 cm at 60 Hz on 8, 7 cm at 100 Hz on 8, and rests
  // sinking 4.8 cm at 120 Hz on 10 (0.003 m/s; 12 substeps: 4.5 cm, 20 % more time).
  int substeps = 10;  // [substeps]
  // Soft step: the contact spring's natural frequency, capped at a fifth of the substep rate
  // (measured in soft_step_solver.cpp; Box2D v3 caps at a quarter, Box3D at an eighth); its
  // damping ratio (Box2D v3's 10: heavily over-damped, so nothing bounces off the spring); and
  // the fastest a penetration is pushed out (Box2D v3's contactSpeed).
  double contactHertz = 120.0;        // [Hz]
  double contactDampingRatio = 10.0;  // [1]
  double contactPushSpeed = 3.0;      // [m/s]
  // Friction of both solvers (docs/scene-format.md, `friction`; docs/contact.md). Cone: the
  // tangential impulse that stops the slip, scaled onto the cone of mu_s or mu_k, the coefficient
  // chosen by the regime the last step ended in (soft step per point, PGS per patch at its centroid
  // with a twist). Seed000: seed 000 "Friction" at every point in every sweep, after its normal
  // row, with the point's K_T: the sticking impulse if inside the mu_s cone, else -mu_k j_n T
  // (engine/src/dynamics/friction_law.h).
  // Both meet the analytic slide and incline; cone stacks better with PGS (REPORT section 5).
  enum class FrictionModel { Cone, Seed000 };
  FrictionModel friction = FrictionModel::Cone;
  // Contact between two bodies that are both non-convex triangle meshes with grids (not implicit
  // shapes). Samples: each body's surface samples against the other's grid (seed 000 "Collision
  // Detection"; collision/narrowphase/sdf_contact.h). Triangles: the segments where the two
  // surfaces cross, by Moller's triangle-triangle test over both meshes' hierarchies
  // (collision/narrowphase/mesh_mesh.h): exact on the meshes, but only once they cross.
  enum class MeshContact { Samples, Triangles };
  MeshContact meshContact = MeshContact::Samples;
  int velocityIterations = 10;  // PGS: [sweeps] over every contact point (Box2D v2's default is 8)
  int positionIterations = 4;   // PGS: [sweeps] of the split-impulse pass (Box2D v2's default is 3)
  // Approach speeds below this do not bounce: a resting body meets the ground at g dt every step,
  // and bouncing that would never let it rest (Box2D's b2_velocityThreshold is 1 m/s).
  double restitutionThreshold = 0.5;  // [m/s]
  // A contact is reported as a hit (contactEvents, world/contact_events.h) when a point of
  // it takes a normal impulse while the bodies approach faster than this: Box2D v3's
  // b2_hitEventThreshold and Box3D's b3WorldDef::hitEventThreshold, 1 m/s. Reading nothing else.
  double hitEventSpeed = 1.0;  // [m/s]
  // Penetration left in place, so that resting contacts stay touching from step to step instead
  // of being pushed apart and falling back (Box2D's b2_linearSlop).
  double contactSlop = 0.005;  // [m]
  // Fraction of the penetration beyond the slop removed per step by the split impulse (Baumgarte's
  // beta; Box2D v2's b2_baumgarte is 0.2). Larger values overshoot in stacks.
  double positionCorrection = 0.2;  // [1]
  // Last step's impulse starts a contact point's iterations when the point, in its body's frame,
  // lies within this distance of last step's (Bullet's contact breaking threshold is 2 cm).
  bool warmStarting = true;
  double warmStartDistance = 0.02;  // [m]

  // Threads that share a step's loops over bodies, pairs and solver islands (oneTBB's pool, which
  // sleeps between loops; math/parallel.h). Each piece of work writes only its own slots and each
  // island is swept in one order, so a step gives bit-identical results for any number of threads.
  int threads = machineThreads();  // [threads], in [1, kMaxThreads]

  // false runs every stage of World::step every step, needed or not: it exists to measure what
  // skipping saves (bench/stage_skip_bench.cpp), never to change results.
  bool skipIdleStages = true;
};

// Contact tolerances (contactMargin, contactSlop): a tolerance, not a reach. Past a metre every
// body near another is a contact pair each step, and the narrow phase runs on all n^2/2.
inline constexpr double kMaxContactTolerance = 1.0;  // [m]
// Settings::contactRecycleDistance's automatic value.
inline constexpr double kAutoRecycleDistance = -1.0;
// The automatic recycling distance in units of |g| h^2, how far gravity moves a body in a substep
// of h squared: a soft contact's sink, and the motions of a resting stack, scale with h^2 (its
// stiffness is capped by the substep rate). 6 keeps the 100-row pyramid standing on 4 substeps
// (1.0 mm: top drift 5.7 cm, where 0.5 mm gave 37 cm and 0.2 mm 2.0 m) and its 10-substep end as
// accurate as without recycling (0.17 mm; 1 mm drifted it 5.2 cm) (docs/speed.md).
inline constexpr double kRecycleGravityFactor = 6.0;  // [1]
// Gravity above the surface gravity of a neutron star (~2e12 m/s^2) is no scene's.
inline constexpr double kMaxGravity = 1e13;  // [m/s^2]
// A query log longer than this holds more than anyone reads, at ~200 B a record.
inline constexpr std::size_t kMaxQueryLogCapacity = 1000000;  // [records]

// The scene names of the methods: "soft-step" | "pgs" | "lcp", "sap" | "brute-force", "samples" | "triangles"
// (scene/scene_parts.cpp reads them, worldBlockJson writes them).
const char* contactSolverName(Settings::ContactSolverMethod method);
const char* broadPhaseName(Settings::BroadPhaseMethod method);
const char* meshContactName(Settings::MeshContact method);
// The scene names of Settings::FrictionModel: "cone", "seed000".
const char* frictionModelName(Settings::FrictionModel model);
// False, leaving `model` alone, for a name that is neither.
bool parseFrictionModel(const std::string& name, Settings::FrictionModel& model);

// What is wrong with a Settings: the scene key of the field (under "world") and what was
// expected. Empty (false) when the settings are usable.
struct SettingsProblem {
  std::string key;          // e.g. "dt", "ccd_motion_fraction"
  std::string expectation;  // "expected ..."
  explicit operator bool() const { return !key.empty(); }
  std::string message() const { return "world." + key + ": " + expectation; }
};

// The one check of every field (World's constructor and the scene loader both use it, so a value
// is refused with the same words wherever it comes from).
SettingsProblem checkSettings(const Settings& settings);
// Settings::contactRecycleDistance in metres: the automatic one worked out, 0 for the PGS solver
// (it collides after moving the bodies; recycling is the soft step's).
double recycleDistance(const Settings& settings);

}  // namespace rbsim
