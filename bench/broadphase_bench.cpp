// Broad-phase update time against the number of boxes (issue 4): SweepAndPrune with coherent
// motion (seed 004 after Cohen et al. 1995: O(n + swaps), near O(n) when motion is coherent),
// with coherent motion slowed as n grows so the swaps per box stay fixed (the O(n) part alone),
// and with every box teleporting each step (its worst case, handled by rebuilding), against
// the O(n^2) BruteForce reference. Only move() and update() are timed, on the thread's CPU
// clock: the machine is shared, and wall time would count the time other processes hold the
// core. The motion is generated outside the clock.
// Counters: pairs (mean overlapping pairs per update), ms_per_update, and for sweep and prune
// the insertion sort's swaps, a rebuild's sweep tests and the fraction of updates that rebuilt.
// Run: build/bench/broadphase_bench   (about 40 s)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>
#include <type_traits>
#include <vector>

#include "collision/broadphase/brute_force.h"
#include "collision/broadphase/sweep_and_prune.h"

namespace {

using namespace rbsim;

constexpr double kMinHalfSize = 0.25;          // [m] box half-sizes uniform in [min, max]
constexpr double kMaxHalfSize = 0.5;           // [m]
constexpr double kOverlapsPerBox = 4.0;        // target mean number of boxes each box overlaps
constexpr double kStepFractionOfSize = 0.02;   // coherent: at most 2 % of the mean size per step
// In a cube filled at fixed density the endpoints on an axis are n^(2/3) times denser at n boxes
// than at one, so a fixed step passes n^(2/3) times more of them: swaps grow as n^(5/3). The
// "fixed swaps" motion scales the step by (kReferenceCount / n)^(2/3) to keep the swaps per box
// of kReferenceCount boxes, which isolates the O(n) part of the cost.
constexpr double kReferenceCount = 1000;
constexpr unsigned kSeed = 2024;

// Boxes in a cube of side L. Two boxes overlap when their centres are within h_i + h_j on every
// axis (mean 2 x 0.375 m), which has probability ~ (2 (h_i + h_j) / L)^3, so a box overlaps
// N (1.5 m / L)^3 others on average: L = 1.5 m (N / kOverlapsPerBox)^(1/3).
struct Scene {
  Scene(int n, double stepScale) : rng(kSeed) {
    const double meanReach = kMinHalfSize + kMaxHalfSize;  // [m] mean h_i + h_j
    side = 2.0 * meanReach * std::cbrt(n / kOverlapsPerBox);
    const double maxStep = stepScale * kStepFractionOfSize * meanReach;  // [m] per step, per axis
    std::uniform_real_distribution<double> halfSize(kMinHalfSize, kMaxHalfSize), unit(-1.0, 1.0);
    for (int i = 0; i < n; ++i) {
      half.emplace_back(halfSize(rng), halfSize(rng), halfSize(rng));
      centre.push_back(randomCentre(half.back()));
      velocity.push_back(maxStep * Vec3(unit(rng), unit(rng), unit(rng)));
    }
  }
  Vec3 randomCentre(const Vec3& h) {
    Vec3 c;
    for (int k = 0; k < 3; ++k) c[k] = std::uniform_real_distribution<double>(h[k], side - h[k])(rng);
    return c;
  }
  Aabb box(std::size_t i) const { return {centre[i] - half[i], centre[i] + half[i]}; }
  // Random walk with constant velocities, bouncing off the walls of the cube.
  void stepCoherent() {
    for (std::size_t i = 0; i < centre.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        double& c = centre[i][k];
        c += velocity[i][k];
        if (c < half[i][k] || c > side - half[i][k]) {
          velocity[i][k] = -velocity[i][k];
          c = std::clamp(c, half[i][k], side - half[i][k]);
        }
      }
    }
  }
  void teleport() {
    for (std::size_t i = 0; i < centre.size(); ++i) centre[i] = randomCentre(half[i]);
  }

  std::mt19937 rng;
  double side = 0;  // [m]
  std::vector<Vec3> centre, velocity, half;
};

enum class Motion { Coherent, CoherentFixedSwaps, Teleport };

double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <typename BroadPhaseT>
void update(benchmark::State& state, Motion motion) {
  const int n = static_cast<int>(state.range(0));
  Scene scene(n, motion == Motion::CoherentFixedSwaps ? std::pow(kReferenceCount / n, 2.0 / 3.0) : 1.0);
  BroadPhaseT bp;
  std::vector<ProxyId> ids;
  for (std::size_t i = 0; i < scene.centre.size(); ++i) ids.push_back(bp.add(scene.box(i)));
  bp.update();
  double pairs = 0, seconds = 0, swaps = 0, sweepTests = 0, rebuilds = 0;
  for (auto _ : state) {
    if (motion == Motion::Teleport) {
      scene.teleport();
    } else {
      scene.stepCoherent();
    }
    const double start = threadSeconds();
    for (std::size_t i = 0; i < ids.size(); ++i) bp.move(ids[i], scene.box(i));
    bp.update();
    const double elapsed = threadSeconds() - start;  // [s]
    state.SetIterationTime(elapsed);
    seconds += elapsed;
    pairs += static_cast<double>(bp.pairs().size());
    if constexpr (std::is_same_v<BroadPhaseT, SweepAndPrune>) {
      swaps += static_cast<double>(bp.lastUpdate().swaps);
      sweepTests += static_cast<double>(bp.lastUpdate().sweepTests);
      rebuilds += bp.lastUpdate().path != SweepAndPrune::Path::Incremental;
    }
  }
  const double updates = static_cast<double>(state.iterations());
  state.counters["pairs"] = pairs / updates;
  state.counters["ms_per_update"] = 1e3 * seconds / updates;
  if constexpr (std::is_same_v<BroadPhaseT, SweepAndPrune>) {
    state.counters["swaps"] = swaps / updates;
    state.counters["sweep_tests"] = sweepTests / updates;
    state.counters["rebuilt"] = rebuilds / updates;
  }
}

void sapCoherent(benchmark::State& s) { update<SweepAndPrune>(s, Motion::Coherent); }
void sapCoherentFixedSwaps(benchmark::State& s) { update<SweepAndPrune>(s, Motion::CoherentFixedSwaps); }
void sapTeleport(benchmark::State& s) { update<SweepAndPrune>(s, Motion::Teleport); }
void bruteCoherent(benchmark::State& s) { update<BruteForce>(s, Motion::Coherent); }
void bruteTeleport(benchmark::State& s) { update<BruteForce>(s, Motion::Teleport); }

BENCHMARK(sapCoherent)->Arg(1000)->Arg(10000)->Arg(50000)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(sapCoherentFixedSwaps)->Arg(1000)->Arg(10000)->Arg(50000)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(sapTeleport)->Arg(1000)->Arg(10000)->Arg(50000)->UseManualTime()->Unit(benchmark::kMillisecond);
// Brute force does n(n-1)/2 tests whatever the motion; at 5e4 (1.25e9 tests) one update is
// timed, after the set-up's own update, to keep the run short.
BENCHMARK(bruteCoherent)->Arg(1000)->Arg(10000)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(bruteCoherent)->Arg(50000)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(bruteTeleport)->Arg(1000)->Arg(10000)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
