#pragma once
// Constitutive models (seed 002 1.1): the first Piola-Kirchhoff stress P(F) of the deformation
// gradient F, the strain energy density psi(F) whose gradient it is, and the differential
// dP = dP/dF : dF that backward Euler needs. Isotropic, from Young's modulus E and Poisson's
// ratio nu through Lame's constants.
#include <string>
#include <vector>

#include "rbsim/math/types.h"

namespace rbsim {

enum class ConstitutiveModel {
  Linear,              // Cauchy strain eps = (F + F^T)/2 - I, P = 2 mu eps + lambda tr(eps) I (seed 002)
  StVenantKirchhoff,   // Green strain G = (F^T F - I)/2, S = 2 mu G + lambda tr(G) I, P = F S (seed 002)
  Corotated,           // F = R S: P = 2 mu (F - R) + lambda tr(R^T F - I) R (linear in the rotated frame)
  NeoHookean,          // P = mu (F - F^-T) + lambda ln(J) F^-T, J = det F > 0
};

const char* constitutiveModelName(ConstitutiveModel model);
bool parseConstitutiveModel(const std::string& name, ConstitutiveModel& model);
std::vector<std::string> constitutiveModelNames();

struct LameParameters {
  double mu = 0.0;      // shear modulus [Pa]
  double lambda = 0.0;  // [Pa]
};

// Seed 002: mu = E / (2 (1 + nu)), lambda = nu E / ((1 + nu)(1 - 2 nu)); nu in (-1, 1/2).
LameParameters lameParameters(double youngsModulus, double poissonRatio);

struct Elasticity {
  ConstitutiveModel model = ConstitutiveModel::Corotated;
  LameParameters lame;
};

// psi(F) [J/m^3]. Neo-Hookean is infinite for J <= 0 (an inverted element).
double strainEnergyDensity(const Elasticity& e, const Mat3& F);
// P(F) = d psi / dF [Pa].
Mat3 firstPiolaStress(const Elasticity& e, const Mat3& F);
// What dP at F needs, computed once per element and step: the implicit solver applies dP many
// times per step, and the polar decomposition and the inverse would dominate it.
struct StressLinearization {
  Mat3 F = Mat3::Identity();
  Mat3 rotation = Mat3::Identity();  // R of F = R S (corotated)
  Mat3 inverse = Mat3::Identity();   // F^-1 (neo-Hookean)
  double logJ = 0.0;                 // ln det F (neo-Hookean)
};
StressLinearization linearize(const Elasticity& e, const Mat3& F);

// dP for a change dF of F. Exact for linear, St. Venant-Kirchhoff and Neo-Hookean; for the
// corotated model the rotation is held fixed (the usual approximation, which keeps the implicit
// system symmetric positive definite).
Mat3 stressDifferential(const Elasticity& e, const StressLinearization& at, const Mat3& dF);
Mat3 stressDifferential(const Elasticity& e, const Mat3& F, const Mat3& dF);

// The rotation of F's polar decomposition F = R S (via the SVD, with det R = +1 even when F is
// inverted, as in Irving, Teran and Fedkiw 2004).
Mat3 polarRotation(const Mat3& F);

}  // namespace rbsim
