// Stacking scenes of issue 18 at dt = 1/60 s, sleep off, 10 s: columns of 10, 20 and 40 unit
// boxes, a pyramid wall of 20 rows (210 boxes) and Box3D's large_pyramid (90 rows, 4095 boxes),
// with each solver and integrator asked for. Prints per run: the top box's horizontal drift,
// the height lost by the column, the farthest any box ended from its start, the deepest
// penetration, the fastest box, and the median ms per step. Not a Google Benchmark: one long run
// per case is the measurement.
//   usage: contact_scenes [--csv FILE] [--scenes a,b] [--solvers soft-step,pgs] [--integrators a,b]
//                         [--dt S] [--substeps N] [--hertz F] [--damping Z] [--push V]   (soft step's settings)
//                         [--friction cone|seed000] [--recycle D|auto]  (world.contact_recycle_distance)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "rbsim/geometry/mesh.h"
#include "rbsim/mass/mass_properties.h"
#include "stack_layout.h"
#include "rbsim/world/world.h"

using namespace rbsim;
using namespace rbsim::bench;

namespace {

struct SceneCase {
  std::string name;
  std::vector<BoxCentre> boxes;
};

std::vector<SceneCase> allScenes() {
  return {{"stack10", columnLayout(10)},     {"stack20", columnLayout(20)},     {"stack40", columnLayout(40)},
          {"pyramid20", pyramidLayout(20)}, {"large_pyramid", pyramidLayout(90)}};
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

struct Result {
  double topDrift = 0.0, heightLost = 0.0, farthest = 0.0, deepest = 0.0, fastest = 0.0, msPerStep = 0.0;
};

Settings base;  // the defaults, with what the command line changed
double timeStep = kStackTimeStep;  // [s]

Result run(const SceneCase& scene, Settings::ContactSolverMethod solver, Integrator integrator) {
  Settings settings = base;
  settings.timeStep = timeStep;
  settings.allowSleep = false;
  settings.solver = solver;
  settings.integrator = integrator;
  World world(settings);
  const Material material{0.0, kStackFriction, kStackFriction};
  world.addPlane(Plane{}, material);
  const Vec3 extents = Vec3::Constant(kStackBoxSize);
  auto mesh = std::make_shared<const Mesh>(makeBox(extents));
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    BodyDef def;
    def.name = "box" + std::to_string(i);
    def.mesh = mesh;
    def.mass = kStackBoxMass;
    def.inertiaBody = cuboidInertia(kStackBoxMass, extents);
    def.shape = Shape::box(0.5 * extents);
    def.material = material;
    def.position = Vec3(scene.boxes[i].x, scene.boxes[i].y, scene.boxes[i].z);
    world.addBody(def);
  }
  const int steps = static_cast<int>(kStackSeconds / timeStep + 0.5);
  std::vector<double> ms;
  for (int s = 0; s < steps; ++s) {
    const auto start = std::chrono::steady_clock::now();
    world.step();
    ms.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  Result r;
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  r.msPerStep = ms[ms.size() / 2];
  const std::size_t top = scene.boxes.size() - 1;
  const RigidBody& topBox = world.bodies()[top];
  const Vec3 start(scene.boxes[top].x, scene.boxes[top].y, scene.boxes[top].z);
  r.topDrift = Vec3(topBox.position().x() - start.x(), 0.0, topBox.position().z() - start.z()).norm();
  r.heightLost = start.y() - topBox.position().y();
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    const Vec3 s(scene.boxes[i].x, scene.boxes[i].y, scene.boxes[i].z);
    r.farthest = std::max(r.farthest, (world.bodies()[i].position() - s).norm());
    r.fastest = std::max(r.fastest, world.bodies()[i].velocity().norm());
  }
  for (const Contact& c : world.contacts()) r.deepest = std::max(r.deepest, c.manifold.maxDepth());
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::string csvPath;
  std::vector<std::string> sceneNames{"stack10", "stack20", "stack40", "pyramid20", "large_pyramid"};
  std::vector<std::string> solverNames{"soft-step", "pgs"};
  std::vector<std::string> integrators{"expmap", "dlm"};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "contact_scenes: %s needs a value\n", arg.c_str());
      return 2;
    }
    if (arg == "--csv") csvPath = argv[++i];
    else if (arg == "--scenes") sceneNames = split(argv[++i]);
    else if (arg == "--solvers") solverNames = split(argv[++i]);
    else if (arg == "--integrators") integrators = split(argv[++i]);
    else if (arg == "--dt") timeStep = std::atof(argv[++i]);
    else if (arg == "--substeps") base.substeps = std::atoi(argv[++i]);
    else if (arg == "--hertz") base.contactHertz = std::atof(argv[++i]);
    else if (arg == "--damping") base.contactDampingRatio = std::atof(argv[++i]);
    else if (arg == "--push") base.contactPushSpeed = std::atof(argv[++i]);
    else if (arg == "--recycle") {
      const std::string d = argv[++i];
      base.contactRecycleDistance = d == "auto" ? kAutoRecycleDistance : std::atof(d.c_str());
    }
    else if (arg == "--friction") {
      if (!parseFrictionModel(argv[++i], base.friction)) {
        std::fprintf(stderr, "contact_scenes: --friction expects cone or seed000, got %s\n", argv[i]);
        return 2;
      }
    }
    else {
      std::fprintf(stderr, "contact_scenes: unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  FILE* csv = csvPath.empty() ? nullptr : std::fopen(csvPath.c_str(), "w");
  if (!csvPath.empty() && csv == nullptr) {
    std::fprintf(stderr, "contact_scenes: cannot write %s\n", csvPath.c_str());
    return 2;
  }
  if (csv) std::fprintf(csv, "scene,boxes,solver,integrator,top_drift_m,height_lost_m,farthest_m,deepest_m,fastest_mps,ms_per_step\n");
  for (const SceneCase& scene : allScenes()) {
    if (std::find(sceneNames.begin(), sceneNames.end(), scene.name) == sceneNames.end()) continue;
    for (const std::string& solverName : solverNames) {
      const auto solver = solverName == "pgs" ? Settings::ContactSolverMethod::Pgs : Settings::ContactSolverMethod::SoftStep;
      for (const std::string& integratorName : integrators) {
        Integrator integrator;
        if (!parseIntegrator(integratorName, integrator)) {
          std::fprintf(stderr, "contact_scenes: unknown integrator %s\n", integratorName.c_str());
          return 2;
        }
        const Result r = run(scene, solver, integrator);
        std::printf("%-14s %5zu boxes  %-9s %-16s top drift %8.4f m  height lost %8.4f m  farthest %8.4f m  deepest %7.4f m  "
                    "fastest %7.4f m/s  %8.3f ms/step\n",
                    scene.name.c_str(), scene.boxes.size(), solverName.c_str(), integratorName.c_str(), r.topDrift, r.heightLost,
                    r.farthest, r.deepest, r.fastest, r.msPerStep);
        std::fflush(stdout);
        if (csv) {
          std::fprintf(csv, "%s,%zu,%s,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", scene.name.c_str(), scene.boxes.size(), solverName.c_str(),
                       integratorName.c_str(), r.topDrift, r.heightLost, r.farthest, r.deepest, r.fastest, r.msPerStep);
        }
      }
    }
  }
  if (csv) std::fclose(csv);
  return 0;
}
