// soft/constitutive: the seed's Lame constants, every model's stress as the gradient of its
// energy, rest and rotation invariance, and the differential used by backward Euler.
#include "rbsim/soft/constitutive.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "rbsim/math/rotation.h"

namespace rbsim {
namespace {

const ConstitutiveModel kModels[] = {ConstitutiveModel::Linear, ConstitutiveModel::StVenantKirchhoff,
                                     ConstitutiveModel::Corotated, ConstitutiveModel::NeoHookean};

Elasticity elasticity(ConstitutiveModel model) { return {model, lameParameters(1e5, 0.3)}; }

Mat3 randomDeformation(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  Mat3 F = Mat3::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) F(i, j) += u(rng);
  }
  return F;
}

TEST(LameParameters, FollowSeed002FromYoungsModulusAndPoissonsRatio) {
  const LameParameters l = lameParameters(2e5, 0.25);
  EXPECT_DOUBLE_EQ(l.mu, 2e5 / 2.5);
  EXPECT_DOUBLE_EQ(l.lambda, 0.25 * 2e5 / (1.25 * 0.5));
  EXPECT_THROW(lameParameters(2e5, 0.5), std::invalid_argument);
  EXPECT_THROW(lameParameters(0.0, 0.3), std::invalid_argument);
}

TEST(Constitutive, StressIsTheEnergyGradient) {
  std::mt19937 rng(7);
  for (ConstitutiveModel model : kModels) {
    const Elasticity e = elasticity(model);
    for (int trial = 0; trial < 20; ++trial) {
      const Mat3 F = randomDeformation(rng, 0.3);
      const Mat3 P = firstPiolaStress(e, F);
      const double h = 1e-6;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          Mat3 plus = F, minus = F;
          plus(i, j) += h;
          minus(i, j) -= h;
          const double numeric = (strainEnergyDensity(e, plus) - strainEnergyDensity(e, minus)) / (2.0 * h);
          EXPECT_NEAR(P(i, j), numeric, 1e-6 * e.lame.lambda) << constitutiveModelName(model) << " (" << i << ", " << j << ")";
        }
      }
    }
  }
}

TEST(Constitutive, NoStressAtRestNorUnderRotationExceptLinear) {
  const Mat3 R = rotationFromAxisAngle(0.8 * Vec3(1.0, 2.0, 0.5).normalized());
  for (ConstitutiveModel model : kModels) {
    const Elasticity e = elasticity(model);
    EXPECT_LT(firstPiolaStress(e, Mat3::Identity()).norm(), 1e-12) << constitutiveModelName(model);
    const double rotated = firstPiolaStress(e, R).norm();
    if (model == ConstitutiveModel::Linear) {
      EXPECT_GT(rotated, 0.1 * e.lame.mu) << "Cauchy strain is not rotation invariant (seed 002)";
    } else {
      EXPECT_LT(rotated, 1e-9 * e.lame.mu) << constitutiveModelName(model);
    }
  }
}

TEST(Constitutive, DifferentialMatchesTheStressChange) {
  std::mt19937 rng(11);
  for (ConstitutiveModel model : kModels) {
    const Elasticity e = elasticity(model);
    for (int trial = 0; trial < 10; ++trial) {
      const Mat3 F = randomDeformation(rng, 0.2);
      const Mat3 dF = randomDeformation(rng, 1.0) - Mat3::Identity();
      const double h = 1e-6;
      const Mat3 numeric = (firstPiolaStress(e, F + h * dF) - firstPiolaStress(e, F - h * dF)) / (2.0 * h);
      const Mat3 analytic = stressDifferential(e, F, dF);
      if (model == ConstitutiveModel::Corotated) {
        // The rotation is held fixed: only the part that does not turn R is exact. Its
        // symmetric approximation still points the same way.
        EXPECT_GT((analytic.array() * numeric.array()).sum(), 0.0);
      } else {
        EXPECT_LT((analytic - numeric).norm(), 1e-5 * numeric.norm() + 1e-3) << constitutiveModelName(model);
      }
    }
  }
}

TEST(Constitutive, PolarRotationIsARotationEvenForInvertedF) {
  const Mat3 R = rotationFromAxisAngle(0.4 * Vec3::UnitZ());
  const Mat3 S = Vec3(1.2, 0.9, 1.1).asDiagonal();
  EXPECT_LT((polarRotation(R * S) - R).norm(), 1e-12);
  Mat3 inverted = R * S;
  inverted.col(2) *= -1.0;
  const Mat3 Q = polarRotation(inverted);
  EXPECT_NEAR(Q.determinant(), 1.0, 1e-12);
  EXPECT_LT((Q * Q.transpose() - Mat3::Identity()).norm(), 1e-12);
}

}  // namespace
}  // namespace rbsim
