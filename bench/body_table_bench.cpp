// The two figures of issue 58 ("one body table with stable keys"):
//  - no scan of every body: a step of a World with 100,000 sleeping boxes and 10 awake ones,
//    against one with 1,000 sleeping and the same 10 awake (goal: at most 1.5x);
//  - removal costs what it touches: World::destroyBody of one box from a resting pile of 10,000,
//    against one from a pile of 1,000 (goal: at most 2x).
// Run: build/bench/body_table_bench [repeats] [--removal | --step]   (median of `repeats` timings,
// 9 by default; --removal or --step runs only that half)
// The sleepers rest on the ground 1 m apart (each touches only the ground); the pile's boxes are
// 5 mm apart, within the contact margin, so each has contacts with its neighbours as well
// (bench/removal_scenes.py's layout). The removed box is the pile's middle one, on a fresh copy of
// the rested World each time, and the copy is not timed.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "rbsim/mass/mass_properties.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"

namespace {

using namespace rbsim;
using Clock = std::chrono::steady_clock;

constexpr double kBox = 0.5;            // [m] box edge
constexpr double kDensity = 1000.0;     // [kg/m^3]
constexpr double kSleeperPitch = 1.0;   // [m] between sleepers' centres: apart
constexpr double kPilePitch = 0.505;    // [m] between pile boxes' centres: 5 mm gaps
constexpr int kAwake = 10;              // the awake boxes, falling
constexpr double kDropHeight = 40.0;    // [m] the awake boxes fall for about 2.8 s
constexpr int kMaxSettleSteps = 600;    // steps allowed for the sleepers to fall asleep
constexpr int kTimedSteps = 150;        // steps timed per repeat (the boxes land after 171)

BodyDef boxDef(const Vec3& position) {
  static const auto mesh = std::make_shared<const Mesh>(makeBox(Vec3::Constant(kBox)));
  BodyDef def;
  def.mesh = mesh;
  def.mass = kDensity * kBox * kBox * kBox;
  def.inertiaBody = cuboidInertia(def.mass, Vec3::Constant(kBox));
  def.position = position;
  return def;
}

World groundWorld() {
  Settings settings;  // the defaults: 1/60 s, soft step, sleep on
  World world(settings);
  world.addPlane(Plane{Vec3::UnitY(), 0.0});
  return world;
}

// Boxes in a square grid on the ground, stepped until all sleep.
World restedGrid(int count, double pitch) {
  World world = groundWorld();
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  for (int i = 0; i < count; ++i) {
    const double x = (i % side - 0.5 * (side - 1)) * pitch;
    const double z = (i / side - 0.5 * (side - 1)) * pitch;
    world.addBody(boxDef(Vec3(x, 0.5 * kBox, z)));
  }
  for (int s = 0; s < kMaxSettleSteps && awakeCount(world) > 0; ++s) world.step();
  if (awakeCount(world) > 0) {
    std::fprintf(stderr, "body_table_bench: %d boxes still awake after %d steps\n", count, kMaxSettleSteps);
    std::exit(1);
  }
  return world;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Seconds per step with `sleeping` boxes asleep and kAwake falling beside them.
double stepTime(int sleeping, int repeats) {
  const World rested = restedGrid(sleeping, kSleeperPitch);
  std::vector<double> perStep;
  for (int r = 0; r < repeats; ++r) {
    World world = rested;
    for (int k = 0; k < kAwake; ++k) world.addBody(boxDef(Vec3(2.0 * k, kDropHeight, -1.0e3)));
    world.step();  // the new bodies' first step builds what they need; not timed
    std::vector<double> stageBefore;
    for (int k = 0; k < static_cast<int>(Stage::Count); ++k) stageBefore.push_back(world.stageStats(static_cast<Stage>(k)).seconds);
    const auto start = Clock::now();
    for (int s = 0; s < kTimedSteps; ++s) world.step();
    perStep.push_back(std::chrono::duration<double>(Clock::now() - start).count() / kTimedSteps);
    if (r == 0 && std::getenv("RBSIM_BENCH_STAGES") != nullptr) {  // where a step's time goes
      for (int k = 0; k < static_cast<int>(Stage::Count); ++k) {
        const StageStats& stats = world.stageStats(static_cast<Stage>(k));
        std::printf("  %d sleeping, %-20s %9.1f us a step\n", sleeping, stageName(static_cast<Stage>(k)),
                    1e6 * (stats.seconds - stageBefore[k]) / kTimedSteps);
      }
    }
    if (awakeCount(world) != static_cast<std::size_t>(kAwake)) {
      std::fprintf(stderr, "body_table_bench: %zu awake, expected %d\n", awakeCount(world), kAwake);
      std::exit(1);
    }
  }
  return median(perStep);
}

// The copy just made sits in the caches as far as it fits: the 1,000-box World's does, the
// 10,000-box World's may not, and a removal from the smaller pile would then run from the cache
// where the larger one's came from memory. Both are timed cold: a pass over a buffer twice the
// last-level cache evicts the copy first. The size is the machine's (sysconf; this one reports
// 260 MiB of L3, and a 64 MiB pass left the 1,000-box pile in it: 1.66x in the median of five
// runs, against 1.1x once evicted).
constexpr std::size_t kEvictFloorBytes = std::size_t{64} << 20;  // [B] when the machine does not say

void evictCaches() {
  static const std::size_t bytes = [] {
    const long l3 = sysconf(_SC_LEVEL3_CACHE_SIZE);
    return std::max(kEvictFloorBytes, l3 > 0 ? 2 * static_cast<std::size_t>(l3) : kEvictFloorBytes);
  }();
  static std::vector<unsigned char> buffer(bytes);
  static unsigned char sink = 0;
  for (std::size_t i = 0; i < buffer.size(); i += 64) {
    buffer[i] = static_cast<unsigned char>(buffer[i] + 1);
    sink = static_cast<unsigned char>(sink ^ buffer[i]);
  }
}

// Seconds for destroyBody of the middle box of a rested pile of `count`.
double removalTime(int count, int repeats) {
  const World rested = restedGrid(count, kPilePitch);
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    World world = rested;
    const BodyId middle = world.idAt(static_cast<std::size_t>(count / 2));
    evictCaches();
    const auto start = Clock::now();
    world.destroyBody(middle);
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  return median(times);
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 9;
  bool step = true, removal = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--removal") {
      step = false;
    } else if (arg == "--step") {
      removal = false;
    } else {
      repeats = std::max(1, std::atoi(argv[i]));
    }
  }
  if (step) {
    const double small = stepTime(1000, repeats), large = stepTime(100000, repeats);
    std::printf("step, 10 awake beside 1,000 sleeping:   %9.1f us\n", 1e6 * small);
    std::printf("step, 10 awake beside 100,000 sleeping: %9.1f us\n", 1e6 * large);
    std::printf("no scan of every body: %.2fx (goal: at most 1.5x)\n", large / small);
  }
  if (!removal) return 0;
  const double one = removalTime(1000, repeats), ten = removalTime(10000, repeats);
  std::printf("destroyBody, pile of 1,000:  %9.1f us\n", 1e6 * one);
  std::printf("destroyBody, pile of 10,000: %9.1f us\n", 1e6 * ten);
  std::printf("removal costs what it touches: %.2fx (goal: at most 2x)\n", ten / one);
  return 0;
}
