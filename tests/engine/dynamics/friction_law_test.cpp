// dynamics/friction_law.h: the two friction laws on one contact point, against hand-computed
// impulses from their formulas.
#include "dynamics/friction_law.h"

#include <cmath>

#include <gtest/gtest.h>

namespace rbsim {
namespace {

FrictionPoint point(double normalImpulse, bool sliding) {
  FrictionPoint p;
  p.slip = {1.0, -1.0};  // [m/s]
  // K_TT = [[0.5, 0.1], [0.1, 0.25]] [1/kg]: masses 1 / 0.5 and 1 / 0.25, coupling 0.1.
  p.tangentMass = {2.0, 4.0};
  p.coupling = 0.1;
  p.normalImpulse = normalImpulse;
  p.staticFriction = 0.5;
  p.kineticFriction = 0.4;
  p.sliding = sliding;
  return p;
}

// Cone: per tangent j_k = -m_k u_k = (-2, 4), |j| = sqrt(20) = 4.472 N s; inside mu_s j_n = 5,
// scaled onto mu j_n = 1 (mu_s, sticking regime) or 0.8 (mu_k, sliding).
TEST(FrictionLaw, ConeStopsEachTangentThenScalesOntoTheCone) {
  const FrictionImpulse inside = coneFriction(point(10.0, false));
  EXPECT_TRUE(inside.sticking);
  EXPECT_NEAR(inside.total[0], -2.0, 1e-15);
  EXPECT_NEAR(inside.total[1], 4.0, 1e-15);
  const FrictionImpulse cut = coneFriction(point(2.0, false));
  EXPECT_FALSE(cut.sticking);
  EXPECT_NEAR(cut.total.norm(), 1.0, 1e-15);
  EXPECT_NEAR(cut.total[1] / cut.total[0], -2.0, 1e-15) << "scaled, not turned";
  EXPECT_NEAR(coneFriction(point(2.0, true)).total.norm(), 0.8, 1e-15);
}

// Seed 000: the sticking impulse j = -K_TT^-1 u = -(1 / 0.115) (0.35, -0.6) = (-3.0435, 5.2174)
// N s (|j| = 6.040), kept inside mu_s j_n; a sliding point takes -mu_k j_n T; a sticking one
// beyond the cone stops at its edge, at the point nearest j in K_TT's metric.
TEST(FrictionLaw, Seed000SticksSlidesOrStopsAtTheConesEdge) {
  const FrictionImpulse stick = seed000Friction(point(20.0, false));
  EXPECT_TRUE(stick.sticking);
  EXPECT_NEAR(stick.total[0], -0.35 / 0.115, 1e-12);
  EXPECT_NEAR(stick.total[1], 0.6 / 0.115, 1e-12);

  const FrictionImpulse slide = seed000Friction(point(2.0, true));
  EXPECT_FALSE(slide.sticking);
  EXPECT_NEAR(slide.total[0], -0.8 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(slide.total[1], 0.8 / std::sqrt(2.0), 1e-15);

  const FrictionImpulse edge = seed000Friction(point(2.0, false));
  EXPECT_FALSE(edge.sticking);
  EXPECT_NEAR(edge.total.norm(), 1.0, 1e-12) << "on the mu_s cone";
  // Nearest in the metric of K: K (j_stick - j) = lambda j with lambda >= 0.
  Eigen::Matrix2d K;
  K << 0.5, 0.1, 0.1, 0.25;
  const Eigen::Vector2d residual = K * (stick.total - edge.total);
  EXPECT_NEAR(residual[0] * edge.total[1] - residual[1] * edge.total[0], 0.0, 1e-12);
  EXPECT_GT(residual.dot(edge.total), 0.0);
  // It differs from the radial cut of the cone's law: the metric turns it.
  EXPECT_GT((edge.total - stick.total.normalized()).norm(), 1e-3);
}

TEST(FrictionLaw, NoNormalImpulseNoFriction) {
  for (const bool sliding : {false, true}) {
    EXPECT_EQ(coneFriction(point(0.0, sliding)).total.norm(), 0.0);
    EXPECT_EQ(seed000Friction(point(0.0, sliding)).total.norm(), 0.0);
  }
}

}  // namespace
}  // namespace rbsim
