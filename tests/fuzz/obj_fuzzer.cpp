// Fuzz target: the OBJ loader on arbitrary text (its line pre-scan, then tinyobjloader), the
// convexity test and the grid and sample budgets, then both inertia methods (with the
// self-crossing check) on the mesh it gives and a few steps of the body dropped on a plane. Only InputError (and, once running,
// SimulationError) may come out; anything else, a crash or a sanitizer report is a bug.
#include <cstdint>
#include <string>

#include "rbsim/geometry/signed_distance_grid.h"
#include "geometry/surface_samples.h"
#include "rbsim/io/input_error.h"
#include "io/obj_loader.h"
#include "rbsim/mass/mass_model.h"
#include "rbsim/integrate/simulation_error.h"
#include "rbsim/world/world.h"

namespace {

constexpr int kSteps = 4;

void dropOnPlane(const rbsim::MassModel& model) {
  rbsim::Settings settings;
  settings.allowSleep = false;
  rbsim::World world(settings);
  rbsim::BodyDef def;
  def.mesh = model.mesh;
  def.mass = model.mass;
  def.inertiaBody = model.inertiaBody;
  def.angularVelocity = rbsim::Vec3(0.3, 1.0, -0.2);
  world.addBody(def);
  rbsim::Plane ground;
  ground.normal = rbsim::Vec3::UnitY();
  ground.offset = model.mesh->boundsMin().y() + 0.01;  // just inside the mesh: a contact at once
  world.addPlane(ground);
  for (int i = 0; i < kSteps; ++i) world.step();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rbsim::Mesh mesh;
  try {
    mesh = rbsim::parseObj(text, "fuzz.obj");
  } catch (const rbsim::InputError&) {
    return 0;
  }
  // The scene loader's next steps for a closed mesh: the convexity test, the grid's and the
  // samples' budgets (a tiny spacing from a tiny mesh is fine; these only count).
  if (mesh.vertices.size() > 0) {
    const rbsim::Vec3 box = mesh.boundsMax() - mesh.boundsMin();
    rbsim::isConvexSurface(mesh, 1e-6 * box.norm());
    if (box.allFinite() && box.maxCoeff() > 0.0) {
      rbsim::sdfBudgetProblem(mesh, {rbsim::kMaxSdfResolution, 3, 2});
      rbsim::surfaceSampleBudgetProblem(mesh, box.maxCoeff() / rbsim::kMaxSdfResolution);
    }
  }
  for (const rbsim::InertiaMethod method : {rbsim::InertiaMethod::Exact, rbsim::InertiaMethod::Cube}) {
    try {
      dropOnPlane(rbsim::buildMassModel(mesh, 1.0, std::nullopt, method));
    } catch (const rbsim::InputError&) {
    } catch (const rbsim::SimulationError&) {
    }
  }
  return 0;
}
