// Issue 55: PGS's normal impulses against the exact reference (world.solver = lcp), as a function of
// PGS's sweeps (Settings::velocityIterations 1..50) and of its run time, on two small resting
// scenes at dt = 1/60 s: a column of 5 unit boxes and a pyramid of 4 rows (10 boxes, touching side
// by side, so its side contacts carry nothing: a degenerate problem).
//
// Each scene is first brought to rest by the LCP solver itself (1 s). Then one contact problem is
// posed to both solvers alike: the bodies as they are, the World's last contacts, the same
// materials and settings. The two solvers are called directly (engine/src/dynamics), so they see
// the same rows: PgsSolver integrates first (its World adds m g dt before the solve), LcpSolver
// after (it adds it itself), so PGS is handed the bodies with v + g dt and LcpSolver the bodies as
// they are: the same velocities without contact impulses, the same targets (c_R = 0). PGS starts
// cold (a new solver, no warm start), which is what its sweeps alone achieve.
//
// The error: per-point normal impulses are not unique when four coplanar points hold one face
// (lcp_pivoting.h), but what they do to the bodies is, so the error is measured in the Delassus norm,
// ||J^T (f_pgs - f_ref)|| in the metric M^-1 = sqrt(df . A df), over the reference's
// ||J^T f_ref||; the largest per-point difference over the largest reference impulse is written
// beside it, and PGS's seed 001 residual: its fastest approach after the solve, max(-w) [m/s].
// The time is the median over kRepeats solves of one solve, on one thread.
//
// The soft step is not compared: per substep it solves a different problem (soft constraints
// with a bias velocity at the substep's poses, then a relax sweep), so its impulses are not those
// of this LCP; at rest only its step total matches the weight's impulse, once its springs settle.
//   usage: lcp_reference [--csv FILE]   (default bench/results/lcp_error.csv under the source dir)
//   plot:  gnuplot -e "csv='bench/results/lcp_error.csv'; png='bench/results/lcp_error.png'" bench/plot_lcp_error.gp
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "dynamics/lcp_solver.h"
#include "dynamics/pgs_solver.h"
#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/world.h"
#include "stack_layout.h"

using namespace rbsim;
using namespace rbsim::bench;

namespace {

constexpr int kMaxSweeps = 50;        // [sweeps] PGS's Settings::velocityIterations: every count up to this
// and these beyond it, which show where PGS's impulses go (to the reference's, or not).
constexpr int kLongSweeps[] = {100, 200, 500, 1000};  // [sweeps]
constexpr int kRepeats = 201;         // [solves] timed per point; the median is kept
constexpr double kSettleSeconds = 1.0;  // [s] of LCP steps before the problem is posed

struct SceneCase {
  std::string name;
  std::vector<BoxCentre> boxes;
};

Settings sceneSettings() {
  Settings s;
  s.timeStep = kStackTimeStep;
  s.allowSleep = false;
  s.solver = Settings::ContactSolverMethod::Lcp;
  s.threads = 1;
  return s;
}

// Frictionless, so that both solvers solve exactly seed 001's normal LCP: with friction the
// tangential impulses can hold self-balanced squeezes (two boxes of a row pushed apart along
// their side contact, held by friction underneath), and then even the normal impulses' effect
// on the bodies is not unique. At rest on level faces nothing needs friction: the scenes stay.
const Material kMaterial{0.0, 0.0, 0.0};

World restingWorld(const SceneCase& scene) {
  World world(sceneSettings());
  world.addPlane(Plane{}, kMaterial);
  const Vec3 extents = Vec3::Constant(kStackBoxSize);
  auto mesh = std::make_shared<const Mesh>(makeBox(extents));
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    BodyDef def;
    def.name = "box" + std::to_string(i);
    def.mesh = mesh;
    def.mass = kStackBoxMass;
    def.inertiaBody = cuboidInertia(kStackBoxMass, extents);
    def.shape = Shape::box(0.5 * extents);
    def.material = kMaterial;
    def.position = Vec3(scene.boxes[i].x, scene.boxes[i].y, scene.boxes[i].z);
    world.addBody(def);
  }
  while (world.time() < kSettleSeconds - 1e-9) world.step();
  return world;
}

// J^T f as the normal impulses f act on each body (seed 002 2.2.1: dP = j, dL = r x j on body 1
// and the opposite on body 2), and its norm in the metric M^-1 (|dP|^2 / m + dL . I^-1 dL).
double delassusNorm(const std::vector<SolvedContactPoint>& points, const std::vector<double>& f,
                    const std::vector<Contact>& contacts, const std::vector<RigidBody>& bodies) {
  std::vector<Vec3> linear(bodies.size(), Vec3::Zero()), angular(bodies.size(), Vec3::Zero());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Contact& c = contacts[points[k].contact];
    const Vec3 j = f[k] * points[k].normal;
    linear[c.b] += j;
    angular[c.b] += (points[k].position - bodies[c.b].position()).cross(j);
    if (c.kind == Contact::Kind::BodyBody) {
      linear[c.a] -= j;
      angular[c.a] -= (points[k].position - bodies[c.a].position()).cross(j);
    }
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].isDynamic()) continue;
    sum += linear[i].squaredNorm() / bodies[i].mass() + angular[i].dot(bodies[i].inverseInertiaWorld() * angular[i]);
  }
  return std::sqrt(sum);
}

// Seed 001's residual after a solve: the fastest approach, max(-w) with w = u_rel,N less its target
// (-gap / dt for a speculative point, else 0: c_R = 0) [m/s].
double fastestApproach(const std::vector<SolvedContactPoint>& points, double dt) {
  double fastest = 0.0;
  for (const SolvedContactPoint& p : points) {
    fastest = std::max(fastest, -(p.normalVelocity - std::min(p.depth, 0.0) / dt));
  }
  return fastest;
}

struct Solve {
  std::vector<SolvedContactPoint> points;
  double microseconds = 0.0;  // median of one solve
  int pivots = 0;             // LcpSolver only
};

// Solves the problem kRepeats times with a new solver each time (PGS cold) and keeps the median time.
template <class Solver>
Solve solveTimed(const std::vector<RigidBody>& bodies, const std::vector<Contact>& contacts, const Settings& settings,
                 bool addGravity) {
  const std::vector<Material> bodyMaterials(bodies.size(), kMaterial), planeMaterials(1, kMaterial);
  std::vector<Joint> joints;
  IdTable<BodyId> bodyIds;  // a World's that never removed a body: each key is its index
  for (std::size_t i = 0; i < bodies.size(); ++i) bodyIds.add();
  std::vector<double> times;
  Solve out;
  for (int r = 0; r < kRepeats; ++r) {
    std::vector<RigidBody> copy = bodies;
    Solver solver;
    const SolverInput input{copy, contacts, joints, bodyIds, bodyMaterials, planeMaterials, settings, addGravity};
    const auto start = std::chrono::steady_clock::now();
    solver.solve(input);
    times.push_back(1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    out.points = solver.points();
    if constexpr (std::is_same_v<Solver, LcpSolver>) out.pivots = solver.lastPivots();
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  out.microseconds = times[times.size() / 2];
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv = std::string(RBSIM_SOURCE_DIR) + "/bench/results/lcp_error.csv";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv = argv[++i];
    } else {
      std::fprintf(stderr, "usage: lcp_reference [--csv FILE]\n");
      return 2;
    }
  }
  std::FILE* out = std::fopen(csv.c_str(), "w");
  if (out == nullptr) {
    std::fprintf(stderr, "lcp_reference: cannot write %s\n", csv.c_str());
    return 1;
  }
  std::fprintf(out, "scene,solver,sweeps,us_per_solve,delassus_error,point_error,approach_mps,points,pivots\n");
  const std::vector<SceneCase> scenes{{"column5", columnLayout(5)}, {"pyramid4", pyramidLayout(4)}};
  for (const SceneCase& scene : scenes) {
    const World world = restingWorld(scene);
    const std::vector<RigidBody> bodies = world.bodies();
    const std::vector<Contact> contacts = world.contacts();
    Settings settings = sceneSettings();
    const Solve reference = solveTimed<LcpSolver>(bodies, contacts, settings, true);
    std::vector<double> f;
    double largest = 0.0;
    for (const SolvedContactPoint& p : reference.points) {
      f.push_back(p.normalImpulse);
      largest = std::max(largest, p.normalImpulse);
    }
    const double referenceNorm = delassusNorm(reference.points, f, contacts, bodies);
    const double referenceApproach = fastestApproach(reference.points, settings.timeStep);
    std::fprintf(out, "%s,lcp,0,%.4g,0,0,%.4g,%zu,%d\n", scene.name.c_str(), reference.microseconds, referenceApproach,
                 f.size(), reference.pivots);
    std::printf("%s: %zu points, LCP reference %.1f us (%d pivots), |J^T f| = %.4g, approach %.3g m/s\n",
                scene.name.c_str(), f.size(), reference.microseconds, reference.pivots, referenceNorm,
                referenceApproach);
    // PGS integrates first: its bodies carry this step's m g dt already.
    std::vector<RigidBody> integrated = bodies;
    for (RigidBody& b : integrated) {
      if (!b.isDynamic()) continue;
      BodyState state = b.state();
      state.linearMomentum += b.mass() * settings.gravity * settings.timeStep;
      b.setState(state);
    }
    settings.solver = Settings::ContactSolverMethod::Pgs;
    std::vector<int> counts;
    for (int sweeps = 1; sweeps <= kMaxSweeps; ++sweeps) counts.push_back(sweeps);
    counts.insert(counts.end(), std::begin(kLongSweeps), std::end(kLongSweeps));
    for (const int sweeps : counts) {
      settings.velocityIterations = sweeps;
      const Solve pgs = solveTimed<PgsSolver>(integrated, contacts, settings, true);
      if (pgs.points.size() != f.size()) {
        std::fprintf(stderr, "lcp_reference: %s: PGS solved %zu points, the reference %zu\n", scene.name.c_str(),
                     pgs.points.size(), f.size());
        return 1;
      }
      std::vector<double> difference(f.size());
      double pointError = 0.0;
      for (std::size_t k = 0; k < f.size(); ++k) {
        difference[k] = pgs.points[k].normalImpulse - f[k];
        pointError = std::max(pointError, std::abs(difference[k]) / largest);
      }
      const double approach = fastestApproach(pgs.points, settings.timeStep);
      const double error = delassusNorm(pgs.points, difference, contacts, bodies) / referenceNorm;
      std::fprintf(out, "%s,pgs,%d,%.4g,%.4g,%.4g,%.4g,%zu,0\n", scene.name.c_str(), sweeps, pgs.microseconds, error,
                   pointError, approach, f.size());
      if (sweeps == 1 || sweeps == 10 || sweeps == kMaxSweeps || sweeps == 1000) {
        std::printf("  pgs %2d sweeps: %.1f us, Delassus-norm error %.3g, largest point error %.3g, "
                    "approach %.3g m/s\n",
                    sweeps, pgs.microseconds, error, pointError, approach);
      }
    }
  }
  std::fclose(out);
  std::printf("wrote %s\n", csv.c_str());
  return 0;
}
