// What skipping unneeded work saves (issue 3). Two pairs of worlds, each timed per step:
//  - stages: moving boxes in zero gravity with no scripted forces and collisions off, so only
//    Integrate and UpdateSleep have work; Settings::skipIdleStages true skips the others, false
//    runs every stage anyway, the collision stages included (results are bit-identical either
//    way, tests/engine/world/sleep_test).
//  - sleep: boxes at rest in zero gravity; with allowSleep they fall asleep after timeToSleep and
//    Integrate is skipped, without it every body is integrated every step.
// Run: build/bench/stage_skip_bench --benchmark_repetitions=3
// The console output ends with the ratios (time of the full work / time when skipping).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "random_boxes.h"
#include "rbsim/world/world.h"
#include "rbsim/world/queries.h"

namespace {

using namespace rbsim;

constexpr int kBodyCounts[] = {1000, 100000};
constexpr std::uint64_t kSeed = 20240302;
// Boxes of random size and pose in zero gravity; moving ones get random velocities and spins.
World boxWorld(int count, bool moving, bool skipIdleStages, bool allowSleep) {
  Settings settings;
  settings.gravity = Vec3::Zero();
  settings.skipIdleStages = skipIdleStages;
  settings.allowSleep = allowSleep;
  settings.detectCollisions = false;  // the unconstrained pipeline, as in throughput_bench
  World world(settings);
  bench::addRandomBoxes(world, count, kSeed, moving);
  return world;
}

void timeSteps(benchmark::State& state, World& world) {
  const std::uint64_t stepsBefore = world.stepCount();
  std::uint64_t runsBefore = 0;
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) runsBefore += world.stageStats(static_cast<Stage>(s)).runs;
  for (auto _ : state) {
    world.step();
    benchmark::DoNotOptimize(world.bodies().back().state());
  }
  std::uint64_t runs = 0;
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) runs += world.stageStats(static_cast<Stage>(s)).runs;
  const double steps = static_cast<double>(world.stepCount() - stepsBefore);
  state.counters["stages_run"] = static_cast<double>(runs - runsBefore) / steps;  // per step
  state.counters["awake"] = static_cast<double>(awakeCount(world));
}

// Moving bodies: only Integrate and UpdateSleep have work.
void stages(benchmark::State& state, bool skipIdleStages) {
  World world = boxWorld(static_cast<int>(state.range(0)), true, skipIdleStages, true);
  timeSteps(state, world);
}

// Bodies at rest; with allowSleep they are stepped until asleep before timing starts.
void sleeping(benchmark::State& state, bool allowSleep) {
  World world = boxWorld(static_cast<int>(state.range(0)), false, true, allowSleep);
  const double settleSeconds = 2.0 * world.settings().timeToSleep;  // [s], comfortably asleep
  while (world.time() < settleSeconds) world.step();
  if (allowSleep && awakeCount(world) != 0) state.SkipWithError("bodies at rest did not fall asleep");
  timeSteps(state, world);
}

// Keeps each run's CPU time per step (the median when repetitions are aggregated) for the
// ratios: CPU time, as for Google Benchmark's rates, is the less disturbed by other processes.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
      seconds_[run.run_name.str()] = run.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(run.time_unit);
    }
  }
  double secondsPerStep(const std::string& name) const {
    const auto it = seconds_.find(name);
    return it == seconds_.end() ? 0.0 : it->second;
  }

 private:
  std::map<std::string, double> seconds_;
};

std::string runName(const char* family, const char* variant, int count) {
  return std::string(family) + "/" + variant + "/" + std::to_string(count);
}

void printRatio(const SummaryReporter& results, const char* what, const std::string& full,
                const std::string& skipping) {
  const double fullSeconds = results.secondsPerStep(full), skipSeconds = results.secondsPerStep(skipping);
  if (fullSeconds <= 0.0 || skipSeconds <= 0.0) return;
  std::printf("  %-34s %10.1f us %10.1f us %8.2fx\n", what, fullSeconds * 1e6, skipSeconds * 1e6,
              fullSeconds / skipSeconds);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (int count : kBodyCounts) {
    for (const auto& [variant, flag] : {std::pair{"run_all", false}, std::pair{"skip_idle", true}}) {
      benchmark::RegisterBenchmark(("stages/" + std::string(variant)).c_str(), stages, flag)
          ->Arg(count)
          ->Unit(benchmark::kMicrosecond);
    }
    for (const auto& [variant, flag] : {std::pair{"no_sleep", false}, std::pair{"sleep", true}}) {
      benchmark::RegisterBenchmark(("rest/" + std::string(variant)).c_str(), sleeping, flag)
          ->Arg(count)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nTime per step, doing everything vs skipping (ratio = saving factor):\n");
  std::printf("  %-34s %13s %13s %9s\n", "", "everything", "skipping", "ratio");
  for (int count : kBodyCounts) {
    const std::string n = std::to_string(count);
    printRatio(reporter, (n + " moving, skipIdleStages").c_str(), runName("stages", "run_all", count),
               runName("stages", "skip_idle", count));
    printRatio(reporter, (n + " at rest, allowSleep").c_str(), runName("rest", "no_sleep", count),
               runName("rest", "sleep", count));
  }
  benchmark::Shutdown();
  return 0;
}
