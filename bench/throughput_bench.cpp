// Throughput of the unconstrained World::step (issue 3): body-steps per second per integrator for
// 1, 1e3 and 1e5 boxes, memcpy bandwidth in and out of cache, and the memory-bandwidth bound
// bandwidth / (bytes per body-step) the step at 1e5 bodies is held against (goal: within 2x).
// Run: build/bench/throughput_bench --benchmark_repetitions=3 --benchmark_min_time=1
// The console output ends with a summary of the bound; --benchmark_out=FILE keeps the JSON.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "random_boxes.h"
#include "memory_bound.h"
#include "rbsim/world/world.h"

namespace {

using namespace rbsim;
using namespace rbsim::bench;

constexpr int kBodyCounts[] = {1, 1000, 100000};
constexpr int kOutOfCacheBodies = 100000;  // the count the 2x goal is stated for
constexpr std::uint64_t kSeed = 20240301;

// Boxes of random size (each its own mesh, so its 8 body-space vertices are its own memory, as
// for bodies loaded from different shapes), random pose, velocity and spin; gravity on and no
// sleeping, so every body is integrated every step.
World boxWorld(Integrator integrator, int count) {
  Settings settings;
  settings.integrator = integrator;
  settings.allowSleep = false;
  settings.detectCollisions = false;  // the unconstrained step: no collision stages
  World world(settings);
  bench::addRandomBoxes(world, count, kSeed);
  return world;
}

// Bytes World::step reads and writes per awake box under gravity with no scripted forces, no
// pose events and sleeping off, field by field from world.cpp, rigid_body.cpp and
// integrator.cpp: each field once, however often the step touches it while it is in cache. A
// field read and rewritten counts twice, as memcpy's source and destination do. The hardware
// moves whole 64-byte lines, so the real traffic is larger (a field an integrator skips still
// comes in with its neighbours): this count, and so the bound, errs on the strict side.
// Gravity is added in the Integrate pass itself (no pass of its own), and world vertices are
// computed when first read after a step, not by the step: it only marks them stale.
struct FieldTraffic {
  const char* field;
  std::size_t readBytes;
  std::size_t writtenBytes;
};
const FieldTraffic kEveryStep[] = {
    {"awake flag; world vertices marked stale", sizeof(bool), sizeof(bool)},
    {"state x, q, P, L", sizeof(BodyState), sizeof(BodyState)},
    {"F, tau (F += m g, read, cleared)", 2 * sizeof(Vec3), 2 * sizeof(Vec3)},
    {"m, 1/m, I_body^-1", 2 * sizeof(double) + sizeof(Mat3), 0},
    {"R, v, omega (rederived)", 0, sizeof(Mat3) + 2 * sizeof(Vec3)},
};

// What each integrator reads of StepInputs besides F, tau, 1/m and I_body^-1 (integrator.cpp).
// I_body, E and the principal moments are reached through StepInputs::inertia.
std::size_t integratorReadBytes(Integrator integrator) {
  switch (integrator) {
    case Integrator::EulerMatrix: return sizeof(Mat3) + 2 * sizeof(Vec3);  // R, v, omega
    case Integrator::EulerQuat:
    case Integrator::ExpMap: return 2 * sizeof(Vec3);                      // v, omega
    case Integrator::SymplecticEuler: return sizeof(Vec3);  // omega: no torque here (R with torque)
    case Integrator::Rk4: return 0;                                        // R(q) from q
    case Integrator::ImplicitGyro: return 2 * sizeof(Mat3) + sizeof(void*);  // R, I_body
    case Integrator::Dlm: return sizeof(Mat3) + sizeof(Vec3) + sizeof(void*);  // E, principal moments
    case Integrator::Newmark: return sizeof(Mat3) + sizeof(Vec3) + sizeof(void*);  // R, v, I_body
    case Integrator::Exact:
    case Integrator::Exact4: return sizeof(void*);  // principal axes and moments (no torque here: no R)
  }
  return 0;
}

std::size_t bytesPerBodyStep(Integrator integrator) {
  std::size_t total = integratorReadBytes(integrator);
  for (const FieldTraffic& f : kEveryStep) total += f.readBytes + f.writtenBytes;
  return total;
}

void stepBodies(benchmark::State& state, Integrator integrator) {
  const int count = static_cast<int>(state.range(0));
  World world = boxWorld(integrator, count);
  for (auto _ : state) {
    world.step();
    benchmark::DoNotOptimize(world.bodies().back().state());
  }
  state.SetItemsProcessed(state.iterations() * count);
  state.counters["bytes_per_body"] = static_cast<double>(bytesPerBodyStep(integrator));
}





std::string stepName(const std::string& integrator, int count) {
  return "step/" + integrator + "/" + std::to_string(count);
}

void printSummary(const SummaryReporter& results, const std::vector<std::size_t>& copySizes) {
  std::printf("\nBytes read + written per body-step by every integrator (world.cpp, rigid_body.cpp):\n");
  for (const FieldTraffic& f : kEveryStep) {
    std::printf("  %-40s read %4zu  written %4zu\n", f.field, f.readBytes, f.writtenBytes);
  }
  std::printf("  plus what the integrator reads of R, v, omega, I_body, E, principal moments\n");
  std::printf("\nmemcpy bandwidth (read + written; GB = 1e9 B, the table above counts 2^30):\n");
  for (std::size_t size : copySizes) {
    std::printf("  %10zu KiB  %7.2f GB/s\n", size / kKiB, results.rate(copyBenchmarkName(size)) / 1e9);
  }
  const double bandwidth = results.rate(copyBenchmarkName(copySizes.back()));
  if (bandwidth <= 0.0) return;  // the filter left out the out-of-cache copy
  std::printf("\nAt %d bodies: bound = %.2f GB/s / (bytes per body-step); goal: bound/x <= 2\n", kOutOfCacheBodies,
              bandwidth / 1e9);
  std::printf("  %-18s %6s %14s %14s %9s\n", "integrator", "bytes", "bound/s", "measured/s", "bound/x");
  for (const std::string& name : integratorNames()) {
    Integrator integrator;
    parseIntegrator(name, integrator);
    const double bytes = static_cast<double>(bytesPerBodyStep(integrator));
    const double measured = results.rate(stepName(name, kOutOfCacheBodies));
    if (measured <= 0.0) continue;
    std::printf("  %-18s %6.0f %14.4g %14.4g %9.2f\n", name.c_str(), bytes, bandwidth / bytes, measured,
                bandwidth / bytes / measured);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const std::string& name : integratorNames()) {
    Integrator integrator;
    parseIntegrator(name, integrator);
    for (int count : kBodyCounts) {
      benchmark::RegisterBenchmark(("step/" + name).c_str(), stepBodies, integrator)
          ->Arg(count)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  // L1, L2, then out of every cache; the last one sets the bound.
  const std::vector<std::size_t> copySizes = {16 * kKiB, 1 * kMiB, outOfCacheBytes()};
  for (std::size_t size : copySizes) {
    benchmark::RegisterBenchmark("memcpy", copyBuffer)->Arg(static_cast<std::int64_t>(size))->Unit(benchmark::kMicrosecond);
  }
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printSummary(reporter, copySizes);
  benchmark::Shutdown();
  return 0;
}
