// Non-convex collisions (issue 9): cost and penetration error against the grid resolution and the
// surface sampling density. A 0.3 m cube rests in a static bowl (cavity radius 0.9 m, seed 000
// "Collision Detection": the cube's samples against the bowl's grid and the bowl's samples against
// the cube's faces); its resting height has the closed form -sqrt(0.9^2 - 2 h^2) + h, so the
// error of the rest position is known, and the narrow phase's time per step is timed by the World.
//
// usage: sdf_contact_bench [CSV]   (writes the table to CSV when given; about 30 s)
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/geometry/signed_distance_grid.h"
#include "geometry/surface_samples.h"
#include "rbsim/mass/mass_model.h"
#include "rbsim/world/world.h"

using namespace rbsim;

namespace {

constexpr double kBowlRadius = 1.0, kBowlWall = 0.1;  // [m]
constexpr double kHalf = 0.15;                        // the cube's half extent [m]
constexpr double kSettle = 4.0, kMeasure = 2.0;       // [s]
constexpr double kDt = 1.0 / 240.0;                   // [s]

struct Row {
  int resolution;
  double spacingCells;  // sample spacing in cells of the bowl's grid; 0: vertices only
  std::size_t samples;
  double buildMs, narrowMs, heightErr, deepest;
};

Row run(int resolution, double spacingCells) {
  Settings settings;
  settings.timeStep = kDt;
  settings.allowSleep = false;  // keep the narrow phase running while measured
  World world(settings);
  const MassModel bowl = buildMassModel(makeBowl(kBowlRadius, kBowlWall, 64, 16), 50.0, std::nullopt, InertiaMethod::Exact);
  BodyDef def;
  def.name = "bowl";
  def.mesh = bowl.mesh;
  def.mass = bowl.mass;
  def.inertiaBody = bowl.inertiaBody;
  def.position = bowl.centerOffset;  // the rim back at y = 0
  def.isStatic = true;
  SdfGridOptions options;
  options.resolution = resolution;
  def.sdf = std::make_shared<const SignedDistanceGrid>(SignedDistanceGrid::build(*def.mesh, options));
  def.surfaceSamples = std::make_shared<const std::vector<Vec3>>(surfaceSamples(*def.mesh, spacingCells * def.sdf->cellSize()));
  const double buildMs = 1e3 * def.sdf->stats().seconds;
  const std::size_t samples = def.surfaceSamples->size();
  world.addBody(def);
  BodyDef cube;
  cube.name = "cube";
  cube.mesh = std::make_shared<const Mesh>(makeBox(Vec3::Constant(2.0 * kHalf)));
  cube.mass = 1.0;
  cube.inertiaBody = cuboidInertia(1.0, Vec3::Constant(2.0 * kHalf));
  cube.position = Vec3(0.0, 0.1, 0.0);
  world.addBody(cube);
  for (int s = 0; s < static_cast<int>(kSettle / kDt); ++s) world.step();
  const StageStats before = world.stageStats(Stage::NarrowPhase);
  double deepest = 0.0;
  for (int s = 0; s < static_cast<int>(kMeasure / kDt); ++s) {
    world.step();
    for (const Contact& c : world.contacts()) deepest = std::max(deepest, c.manifold.maxDepth());
  }
  const StageStats after = world.stageStats(Stage::NarrowPhase);
  const double cavity = kBowlRadius - kBowlWall;
  const double expected = -std::sqrt(cavity * cavity - 2.0 * kHalf * kHalf) + kHalf;
  const double narrowMs = 1e3 * (after.seconds - before.seconds) / static_cast<double>(after.runs - before.runs);
  return {resolution, spacingCells, samples, buildMs, narrowMs, world.bodies()[1].position().y() - expected, deepest};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<Row> rows;
  for (int resolution : {8, 16, 32, 64, 128}) {
    for (double spacing : {0.0, 1.0}) rows.push_back(run(resolution, spacing));
  }
  std::printf("%10s %8s %8s %10s %12s %16s %14s\n", "resolution", "spacing", "samples", "build ms", "narrow ms",
              "height error m", "deepest m");
  for (const Row& r : rows) {
    std::printf("%10d %8.1f %8zu %10.1f %12.4f %16.2e %14.2e\n", r.resolution, r.spacingCells, r.samples, r.buildMs,
                r.narrowMs, r.heightErr, r.deepest);
  }
  if (argc > 1) {
    std::ofstream csv(argv[1]);
    csv << "resolution,spacing_cells,samples,build_ms,narrow_ms,height_err_m,deepest_m\n";
    for (const Row& r : rows) {
      csv << r.resolution << ',' << r.spacingCells << ',' << r.samples << ',' << r.buildMs << ',' << r.narrowMs << ','
          << r.heightErr << ',' << r.deepest << '\n';
    }
  }
  return 0;
}
