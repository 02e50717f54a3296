#include "rbsim/body/mass_ranges.h"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "rbsim/math/format_number.h"
#include "rbsim/math/physical_ranges.h"

namespace rbsim {

namespace {
// Relative asymmetry |I - I^T| / |I| a tensor typed or computed in doubles may have (RigidBody's own check).
constexpr double kSymmetryTolerance = 1e-9;  // [1]
}  // namespace

std::string massProblem(double mass) {
  if (!std::isfinite(mass)) return "expected a finite number";
  return mass > 0.0 ? std::string() : "expected a positive number, got " + formatNumber(mass);
}

std::string inertiaProblem(const Mat3& inertia) {
  const std::string expected = "expected a symmetric positive definite 3 x 3 tensor in kg m^2 (about the centre of mass, body frame)";
  if (!inertia.allFinite() || (inertia - inertia.transpose()).norm() > kSymmetryTolerance * inertia.norm()) return expected;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia, Eigen::EigenvaluesOnly);
  return eig.eigenvalues().minCoeff() > 0.0 ? std::string() : expected;
}

std::string massScaleProblem(double mass, const Mat3& inertia) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia, Eigen::EigenvaluesOnly);
  const double least = eig.eigenvalues().minCoeff(), most = eig.eigenvalues().maxCoeff();
  if (withinMassScale(mass) && withinMassScale(least) && withinMassScale(most)) return {};
  const auto shown = [](double x) { return formatPastLimit(x, x >= 1.0 ? kMaxMassScale : 1.0 / kMaxMassScale); };
  return "a mass of " + shown(mass) + " kg with principal moments of inertia from " + shown(least) + " to " + shown(most) +
         " kg m^2; " + kMassScaleExpectation;
}

}  // namespace rbsim
