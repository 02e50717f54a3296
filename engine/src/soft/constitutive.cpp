#include "rbsim/soft/constitutive.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/SVD>

namespace rbsim {

namespace {

struct ModelName {
  ConstitutiveModel model;
  const char* name;
};
constexpr ModelName kModelNames[] = {
    {ConstitutiveModel::Linear, "linear"},
    {ConstitutiveModel::StVenantKirchhoff, "stvk"},
    {ConstitutiveModel::Corotated, "corotated"},
    {ConstitutiveModel::NeoHookean, "neo-hookean"},
};

double doubleContraction(const Mat3& a, const Mat3& b) { return (a.array() * b.array()).sum(); }

// The two strain measures of seed 002 1.1: Cauchy's, linear in F, and Green's, zero under rotation.
Mat3 cauchyStrain(const Mat3& F) { return 0.5 * (F + F.transpose()) - Mat3::Identity(); }
Mat3 greenStrain(const Mat3& F) { return 0.5 * (F.transpose() * F - Mat3::Identity()); }

}  // namespace

const char* constitutiveModelName(ConstitutiveModel model) {
  for (const ModelName& m : kModelNames) {
    if (m.model == model) return m.name;
  }
  return "unknown";
}

bool parseConstitutiveModel(const std::string& name, ConstitutiveModel& model) {
  for (const ModelName& m : kModelNames) {
    if (name == m.name) {
      model = m.model;
      return true;
    }
  }
  return false;
}

std::vector<std::string> constitutiveModelNames() {
  std::vector<std::string> names;
  for (const ModelName& m : kModelNames) names.push_back(m.name);
  return names;
}

LameParameters lameParameters(double youngsModulus, double poissonRatio) {
  if (!(youngsModulus > 0.0) || !std::isfinite(youngsModulus) || !(poissonRatio > -1.0) || !(poissonRatio < 0.5)) {
    throw std::invalid_argument("expected Young's modulus > 0 and Poisson's ratio in (-1, 0.5)");
  }
  const LameParameters lame{youngsModulus / (2.0 * (1.0 + poissonRatio)),
                            poissonRatio * youngsModulus / ((1.0 + poissonRatio) * (1.0 - 2.0 * poissonRatio))};
  if (!std::isfinite(lame.lambda) || !std::isfinite(lame.mu) || !std::isfinite(lame.lambda + 2.0 * lame.mu)) {
    throw std::invalid_argument("Lame's constants of E = " + std::to_string(youngsModulus) + " Pa and nu = " +
                                std::to_string(poissonRatio) + " overflow (lambda + 2 mu must be finite)");
  }
  return lame;
}

Mat3 polarRotation(const Mat3& F) {
  Eigen::JacobiSVD<Mat3> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 u = svd.matrixU();
  const Mat3 v = svd.matrixV();
  // A reflection in U V^T goes into the smallest singular value's column: R stays a rotation and
  // an inverted element is pushed back by the stress instead of being treated as a mirror image.
  if ((u * v.transpose()).determinant() < 0.0) u.col(2) *= -1.0;
  return u * v.transpose();
}

double strainEnergyDensity(const Elasticity& e, const Mat3& F) {
  const double mu = e.lame.mu, lambda = e.lame.lambda;
  const Mat3 I = Mat3::Identity();
  switch (e.model) {
    case ConstitutiveModel::Linear: {
      const Mat3 eps = cauchyStrain(F);
      return mu * doubleContraction(eps, eps) + 0.5 * lambda * eps.trace() * eps.trace();
    }
    case ConstitutiveModel::StVenantKirchhoff: {
      const Mat3 G = greenStrain(F);
      return mu * doubleContraction(G, G) + 0.5 * lambda * G.trace() * G.trace();
    }
    case ConstitutiveModel::Corotated: {
      const Mat3 R = polarRotation(F);
      const double t = (R.transpose() * F - I).trace();
      return mu * (F - R).squaredNorm() + 0.5 * lambda * t * t;
    }
    case ConstitutiveModel::NeoHookean: {
      const double J = F.determinant();
      if (!(J > 0.0)) return std::numeric_limits<double>::infinity();
      const double logJ = std::log(J);
      return 0.5 * mu * ((F.transpose() * F).trace() - 3.0) - mu * logJ + 0.5 * lambda * logJ * logJ;
    }
  }
  return 0.0;
}

Mat3 firstPiolaStress(const Elasticity& e, const Mat3& F) {
  const double mu = e.lame.mu, lambda = e.lame.lambda;
  const Mat3 I = Mat3::Identity();
  switch (e.model) {
    case ConstitutiveModel::Linear: {
      const Mat3 eps = cauchyStrain(F);
      return 2.0 * mu * eps + lambda * eps.trace() * I;
    }
    case ConstitutiveModel::StVenantKirchhoff: {
      const Mat3 G = greenStrain(F);
      return F * (2.0 * mu * G + lambda * G.trace() * I);
    }
    case ConstitutiveModel::Corotated: {
      const Mat3 R = polarRotation(F);
      return 2.0 * mu * (F - R) + lambda * (R.transpose() * F - I).trace() * R;
    }
    case ConstitutiveModel::NeoHookean: {
      const double J = F.determinant();
      if (!(J > 0.0)) throw std::domain_error("neo-Hookean stress of an inverted element (det F <= 0)");
      const Mat3 FinvT = F.inverse().transpose();
      return mu * (F - FinvT) + lambda * std::log(J) * FinvT;
    }
  }
  return Mat3::Zero();
}

StressLinearization linearize(const Elasticity& e, const Mat3& F) {
  StressLinearization at;
  at.F = F;
  if (e.model == ConstitutiveModel::Corotated) at.rotation = polarRotation(F);
  if (e.model == ConstitutiveModel::NeoHookean) {
    const double J = F.determinant();
    if (!(J > 0.0)) throw std::domain_error("neo-Hookean stress of an inverted element (det F <= 0)");
    at.inverse = F.inverse();
    at.logJ = std::log(J);
  }
  return at;
}

Mat3 stressDifferential(const Elasticity& e, const StressLinearization& at, const Mat3& dF) {
  const double mu = e.lame.mu, lambda = e.lame.lambda;
  const Mat3 I = Mat3::Identity();
  const Mat3& F = at.F;
  switch (e.model) {
    case ConstitutiveModel::Linear:
      return mu * (dF + dF.transpose()) + lambda * dF.trace() * I;
    case ConstitutiveModel::StVenantKirchhoff: {
      const Mat3 G = greenStrain(F);
      const Mat3 dG = 0.5 * (dF.transpose() * F + F.transpose() * dF);
      return dF * (2.0 * mu * G + lambda * G.trace() * I) + F * (2.0 * mu * dG + lambda * dG.trace() * I);
    }
    case ConstitutiveModel::Corotated:
      return 2.0 * mu * dF + lambda * (at.rotation.transpose() * dF).trace() * at.rotation;
    case ConstitutiveModel::NeoHookean: {
      const Mat3 FinvT = at.inverse.transpose();
      return mu * dF + (mu - lambda * at.logJ) * FinvT * dF.transpose() * FinvT + lambda * (at.inverse * dF).trace() * FinvT;
    }
  }
  return Mat3::Zero();
}

Mat3 stressDifferential(const Elasticity& e, const Mat3& F, const Mat3& dF) {
  return stressDifferential(e, linearize(e, F), dF);
}

}  // namespace rbsim
