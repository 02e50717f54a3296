// Box pile benchmark (issues 5 and 18), with soft step and with PGS: N unit boxes dropped in a loose grid onto a plane (pile_layout.h,
// the same pile bullet_pile drops in Bullet), dt = 1/60 s, 10 solver sweeps, 600 steps. Prints, per N: the median ms per step over the last 300 steps,
// the contact points, the deepest penetration, whether the pile is at rest, and how the stages
// share the time, with sleeping on (as engines run) and off. Not a Google Benchmark: one long run per N is the measurement.
//   usage: contact_pile [N ...]   (default 100 1000 4000)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "pile_layout.h"
#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/world.h"
#include "rbsim/world/queries.h"

using namespace rbsim;
using namespace rbsim::bench;

namespace {

constexpr double kDt = kPileTimeStep;
constexpr int kSteps = kPileSteps;
constexpr int kTimedSteps = kPileTimedSteps;
constexpr double kRestSpeed = kPileRestSpeed;

void runPile(int count, bool allowSleep, Settings::ContactSolverMethod solver) {
  Settings settings;
  settings.solver = solver;
  settings.allowSleep = allowSleep;
  settings.timeStep = kDt;
  settings.velocityIterations = kPileSolverIterations;
  World world(settings);
  // One friction coefficient for sticking and sliding, as Bullet has.
  const Material material{0.0, kPileFriction, kPileFriction};
  world.addPlane(Plane{}, material);
  const Vec3 extents = Vec3::Constant(kPileBoxSize);
  auto mesh = std::make_shared<const Mesh>(makeBox(extents));
  for (int i = 0; i < count; ++i) {
    BodyDef def;
    def.name = "box" + std::to_string(i);
    def.mesh = mesh;
    def.mass = kPileBoxMass;
    def.inertiaBody = cuboidInertia(kPileBoxMass, extents);
    def.shape = Shape::box(0.5 * extents);
    def.material = material;
    const PileCentre c = pileBoxCentre(i, count);
    def.position = Vec3(c.x, c.y, c.z);
    world.addBody(def);
  }
  std::vector<double> ms;
  for (int step = 0; step < kSteps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    world.step();
    ms.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::vector<double> tail(ms.end() - kTimedSteps, ms.end());
  std::nth_element(tail.begin(), tail.begin() + kTimedSteps / 2, tail.end());
  double deepest = 0.0, fastest = 0.0;
  std::size_t points = 0;
  for (const Contact& c : world.contacts()) {
    deepest = std::max(deepest, c.manifold.maxDepth());
    points += static_cast<std::size_t>(c.manifold.count);
  }
  for (const RigidBody& b : world.bodies()) fastest = std::max(fastest, b.velocity().norm());
  std::printf("%-9s N = %5d, sleep %-3s: %8.3f ms/step (median of last %d of %d), %6zu contact points, deepest %.4f m, "
              "fastest %.4f m/s (%s), %zu awake\n",
              solver == Settings::ContactSolverMethod::Pgs ? "pgs" : "soft-step", count, allowSleep ? "on" : "off", tail[kTimedSteps / 2], kTimedSteps, kSteps, points, deepest, fastest,
              fastest < kRestSpeed ? "at rest" : "moving", awakeCount(world));
  double total = 0.0;
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) total += world.stageStats(static_cast<Stage>(s)).seconds;
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) {
    const StageStats& st = world.stageStats(static_cast<Stage>(s));
    if (st.runs > 0) std::printf("    %-22s %5.1f %%\n", stageName(static_cast<Stage>(s)), 100.0 * st.seconds / total);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> counts;
  for (int i = 1; i < argc; ++i) counts.push_back(std::atoi(argv[i]));
  if (counts.empty()) counts = {100, 1000, 4000};
  for (int count : counts) {
    if (count <= 0) {
      std::fprintf(stderr, "contact_pile: expected positive box counts\n");
      return 2;
    }
    for (const auto solver : {Settings::ContactSolverMethod::SoftStep, Settings::ContactSolverMethod::Pgs}) {
      runPile(count, true, solver);
      runPile(count, false, solver);
    }
  }
  return 0;
}
