// FEM soft-body cost (issue 10): a block of about 1e3 and 1e4 tetrahedra, dropped onto the ground,
// stepped by symplectic Euler at 0.9 of its stable step and by backward Euler at 1/240 s and
// 1/60 s. Prints per case: the stable explicit step, ms per step (median of 100 steps after 20),
// CG iterations, and ms of computing per simulated second. Not a Google Benchmark: one run each.
//   usage: soft_bench [E ...]   Young's moduli in Pa (default 1e5, a jelly, and 1e7, a rubber)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "rbsim/soft/soft_body.h"

using namespace rbsim;

namespace {

constexpr int kWarmSteps = 20;
constexpr int kTimedSteps = 100;
constexpr double kExplicitFraction = 0.9;  // of the stable step
constexpr double kBlockSize = 1.0;         // [m] edge
constexpr double kDensity = 1000.0;        // [kg/m^3]
constexpr double kPoissonRatio = 0.3;
constexpr double kDamping = 20.0;          // [Pa s]

void run(int cells, double youngsModulus, SoftIntegrator integrator, double dt, ConstitutiveModel model) {
  SoftBodyDef def;
  def.mesh = makeTetBox(Vec3::Constant(kBlockSize), cells, cells, cells);
  def.position = Vec3(0.0, 0.6, 0.0);
  def.density = kDensity;
  def.youngsModulus = youngsModulus;
  def.poissonRatio = kPoissonRatio;
  def.damping = kDamping;
  def.model = model;
  def.integrator = integrator;
  SoftBody body(def);
  if (dt <= 0.0) dt = kExplicitFraction * body.stableTimeStep();
  const std::vector<Plane> ground = {Plane{}};
  const std::vector<Material> groundMaterial = {Material{}};
  std::vector<double> ms;
  int iterations = 0;
  for (int step = 0; step < kWarmSteps + kTimedSteps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    body.step(dt, Vec3(0.0, -9.81, 0.0), ground, groundMaterial);
    const double elapsed = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (step >= kWarmSteps) {
      ms.push_back(elapsed);
      iterations += body.lastIterations();
    }
  }
  std::nth_element(ms.begin(), ms.begin() + kTimedSteps / 2, ms.end());
  const double median = ms[kTimedSteps / 2];
  std::printf("%6zu tets  E %.0e Pa  %-11s %-16s dt %.2e s (stable explicit %.2e s)  %8.3f ms/step  %5.1f CG its  %9.1f ms per simulated s\n",
              body.tetCount(), youngsModulus, constitutiveModelName(model), softIntegratorName(integrator), dt,
              body.stableTimeStep(), median, static_cast<double>(iterations) / kTimedSteps, median / dt);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> moduli;
  for (int i = 1; i < argc; ++i) moduli.push_back(std::atof(argv[i]));
  if (moduli.empty()) moduli = {1e5, 1e7};
  for (double E : moduli) {
    if (!(E > 0.0)) {
      std::fprintf(stderr, "soft_bench: expected positive Young's moduli\n");
      return 2;
    }
    for (int cells : {6, 12}) {  // 6 * 6^3 = 1296 and 6 * 12^3 = 10368 tetrahedra
      run(cells, E, SoftIntegrator::SymplecticEuler, 0.0, ConstitutiveModel::Corotated);
      run(cells, E, SoftIntegrator::BackwardEuler, 1.0 / 240.0, ConstitutiveModel::Corotated);
      run(cells, E, SoftIntegrator::BackwardEuler, 1.0 / 60.0, ConstitutiveModel::Corotated);
    }
  }
  return 0;
}
