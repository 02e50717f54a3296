// Box3D's own benchmark scenes (erincatto/box3d shared/benchmarks.c, commit 30c67b5), written as
// rbsim scene files in assets/scenes/box3d/ (issue 34): large_pyramid, many_pyramids, joint_grid
// and convex_pile (issue 34), washer and rain (issue 40), junkyard, large_world, trees100, trees50
// and trees25, each run for the steps Box3D's `benchmark` program runs it. Prints per scene:
// the load time (scene file to World), wall and CPU ms per step (median and mean), each stage's
// share, and the end state: the fastest body, the top body's drift and sink, the deepest
// penetration (at the end, and each step's over the second half: mean and worst) and the bodies
// awake. Not a Google Benchmark: one long run per scene is the
// measurement, as in Box3D's program.
//   usage: box3d_scenes [--scenes a,b] [--steps N] [--seconds S] [--threads N] [--set key=value]...
//   A name ending in .json is any scene file, run the same way (200 steps unless told).
//   --steps overrides every scene's step count; --seconds runs S simulated seconds instead (the
//   rest check: large_pyramid for 10 s).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "box3d_cases.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/queries.h"
#include "rbsim/world/world.h"

using namespace rbsim;

namespace {

struct SceneCase {
  std::string name;  // in assets/scenes/box3d, or a path to any scene file (ending in .json)
  int steps;         // Box3D's benchmark program's step count for the scene
};

void run(const SceneCase& scene, int steps, double seconds, const std::vector<std::string>& overrides) {
  const bool file = scene.name.size() > 5 && scene.name.compare(scene.name.size() - 5, 5, ".json") == 0;
  const std::string path = file ? scene.name : std::string(RBSIM_SOURCE_DIR) + "/assets/scenes/box3d/" + scene.name + ".json";
  const auto loadStart = std::chrono::steady_clock::now();
  const Scene loaded = loadScene(path, overrides);
  World world = buildWorld(loaded);
  const double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
  if (seconds > 0.0) steps = static_cast<int>(std::lround(seconds / world.settings().timeStep));

  // The top body: the highest dynamic one at the start, the first made on a tie (a static body
  // never moves, and the joint grid's body 0 is its static anchor row above every sphere).
  std::vector<Vec3> start;
  std::size_t top = world.bodies().size();
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    start.push_back(world.bodies()[i].position());
    if (world.bodies()[i].isDynamic() && (top == world.bodies().size() || start[i].y() > start[top].y())) top = i;
  }
  if (top == world.bodies().size()) top = 0;  // no dynamic body at the start (large_world spawns them)
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(steps));
  const double cpu0 = bench::processCpuSeconds();
  const auto wall0 = std::chrono::steady_clock::now();
  // Each step's deepest overlap over the second half of the run, read outside the step's time:
  // one end-state reading of a falling pile is a single sample of a noisy figure.
  const auto deepestNow = [&world] {
    double d = 0.0;
    for (const Contact& c : world.contacts()) d = std::max(d, c.manifold.maxDepth());
    return d;
  };
  double halfSum = 0.0, halfMax = 0.0, readSeconds = 0.0;
  int halfCount = 0;
  for (int s = 0; s < steps; ++s) {
    const auto t0 = std::chrono::steady_clock::now();
    world.step();
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(1e3 * std::chrono::duration<double>(t1 - t0).count());
    if (2 * s >= steps) {
      const double d = deepestNow();
      halfSum += d;
      halfMax = std::max(halfMax, d);
      ++halfCount;
      readSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count() - readSeconds;
  const double cpu = bench::processCpuSeconds() - cpu0 - readSeconds;

  double fastest = 0.0, deepest = 0.0;
  std::size_t awake = 0, dynamic = 0;
  for (const RigidBody& b : world.bodies()) {
    if (!b.isDynamic()) continue;
    ++dynamic;
    fastest = std::max(fastest, b.velocity().norm());
    if (b.awake()) ++awake;
  }
  deepest = deepestNow();
  const Vec3 topNow = world.bodies()[top].position();
  const double drift = std::hypot(topNow.x() - start[top].x(), topNow.z() - start[top].z());
  const double sink = start[top].y() - topNow.y();
  std::vector<double> sorted = ms;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  std::printf("%-14s %6zu bodies %5zu joints  load %7.3f s  %5d steps  wall %8.2f ms/step (median %8.2f)  cpu %8.2f "
              "ms/step  threads %d\n",
              scene.name.c_str(), dynamic, world.joints().size(), loadSeconds, steps, 1e3 * wall / steps,
              sorted[sorted.size() / 2], 1e3 * cpu / steps, world.settings().threads);
  std::printf("%-14s end: fastest %.4f m/s  top drift %.4f m  top sink %.4f m  deepest %.4f m  awake %zu  contacts %zu"
              " (recycled %zu)\n",
              scene.name.c_str(), fastest, drift, sink, deepest, awake, world.contacts().size(), recycledContacts(world));
  std::printf("%-14s deepest over steps %d-%d: mean %.4f m  worst %.4f m\n", scene.name.c_str(), steps - halfCount,
              steps - 1, halfSum / std::max(halfCount, 1), halfMax);
  double total = 0.0;
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) total += world.stageStats(static_cast<Stage>(s)).seconds;
  std::printf("%-14s stages:", scene.name.c_str());
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) {
    const StageStats& st = world.stageStats(static_cast<Stage>(s));
    if (st.seconds > 0.005 * total) std::printf("  %s %.0f%%", stageName(static_cast<Stage>(s)), 100.0 * st.seconds / total);
  }
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names;
  std::vector<std::string> overrides;
  int steps = 0;
  double seconds = 0.0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "box3d_scenes: %s needs a value\n", arg.c_str());
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--scenes") names = bench::splitCommas(value);
    else if (arg == "--steps") steps = std::atoi(value.c_str());
    else if (arg == "--seconds") seconds = std::atof(value.c_str());
    else if (arg == "--threads") overrides.push_back("world.threads=" + value);
    else if (arg == "--set") overrides.push_back(value);
    else {
      std::fprintf(stderr, "box3d_scenes: unknown option %s\n", arg.c_str());
      return 2;
    }
  }
  for (const std::string& name : names) {
    const bool file = name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0;
    if (!file && std::none_of(std::begin(bench::kBox3dScenes), std::end(bench::kBox3dScenes),
                              [&](const bench::Box3dScene& s) { return name == s.name; })) {
      std::fprintf(stderr, "box3d_scenes: --scenes: no scene \"%s\"; expected large_pyramid, many_pyramids, joint_grid, convex_pile, washer, rain, junkyard, large_world, trees100, trees50, trees25 or a .json file\n", name.c_str());
      return 2;
    }
  }
  try {
    for (const bench::Box3dScene& scene : bench::kBox3dScenes) {
      if (!names.empty() && std::find(names.begin(), names.end(), scene.name) == names.end()) continue;
      run({scene.name, scene.steps}, steps > 0 ? steps : scene.steps, seconds, overrides);
    }
    for (const std::string& name : names) {  // scene files named by path: the steps or seconds asked for, else 200
      if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0) run({name, 200}, steps > 0 ? steps : 200, seconds, overrides);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "box3d_scenes: %s\n", e.what());
    return 2;
  }
  return 0;
}
