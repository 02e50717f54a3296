// Plot ticks a student can read (issue 38): 1-2-5 steps that cover the data, one precision for all
// labels, a shared power of ten for very large or small values, and no tick below zero for a
// quantity that cannot be negative (the old axes showed "-0.68" contact points).
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "render/plot_ticks.h"

namespace rbsim::render {
namespace {

// The step's leading digit: 1, 2 or 5.
double mantissa(double step) { return step / std::pow(10.0, std::floor(std::log10(step) + 1e-9)); }

TEST(PlotTicks, RawExtremesBecomeOneTwoFiveSteps) {
  const AxisTicks t = niceTicks(0.4069, 0.4085, 5, true);  // the old axis: "0.4085 / 0.4077 / 0.4069"
  EXPECT_NEAR(mantissa(t.step), 5.0, 1e-9);
  EXPECT_NEAR(t.step, 5e-4, 1e-12);
  EXPECT_LE(t.lo, 0.4069);
  EXPECT_GE(t.hi, 0.4085);
  ASSERT_EQ(t.labels.size(), 5u);
  EXPECT_EQ(t.labels.front(), "0.4065");
  EXPECT_EQ(t.labels.back(), "0.4085");
  EXPECT_EQ(t.exponent, 0);
}

TEST(PlotTicks, AQuantityThatCannotBeNegativeHasNoTickBelowZero) {
  for (const auto& [lo, hi] : {std::pair{0.0, 0.0}, std::pair{0.7437, 0.7437}, std::pair{0.0, 3.0}, std::pair{1e-9, 2e-9}}) {
    const AxisTicks t = niceTicks(lo, hi, 4, true);
    EXPECT_GE(t.lo, 0.0) << lo << ".." << hi;
    for (const std::string& label : t.labels) EXPECT_EQ(label.find('-'), std::string::npos) << label;
  }
  EXPECT_LT(niceTicks(-0.5, 0.5, 4, false).lo, 0.0);  // a potential energy may go below zero
}

TEST(PlotTicks, VeryLargeAndSmallValuesShareAPowerOfTen) {
  const AxisTicks small = niceTicks(1.2e-5, 3.4e-5, 4, true);
  EXPECT_EQ(small.exponent, -5);
  EXPECT_EQ(axisUnit(small, "rad"), " [x1e-5 rad]");
  EXPECT_EQ(small.labels.back().find('e'), std::string::npos) << small.labels.back();
  const AxisTicks large = niceTicks(2.0e5, 2.6e5, 4, false);
  EXPECT_EQ(large.exponent, 5);
  EXPECT_EQ(axisUnit(niceTicks(1.0, 2.0, 3, false), "J"), " [J]");
}

TEST(PlotTicks, RandomRangesGetFewEvenTicksCoveringTheData) {
  std::mt19937 random(38);
  std::uniform_real_distribution<double> exponent(-8.0, 8.0), unit(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double scale = std::pow(10.0, exponent(random));
    double lo = unit(random) * scale, hi = unit(random) * scale;
    if (lo > hi) std::swap(lo, hi);
    const int maxTicks = 2 + trial % 5;
    const AxisTicks t = niceTicks(lo, hi, maxTicks, false);
    const double m = mantissa(t.step);
    EXPECT_TRUE(std::abs(m - 1.0) < 1e-6 || std::abs(m - 2.0) < 1e-6 || std::abs(m - 5.0) < 1e-6) << t.step;
    EXPECT_LE(t.values.size(), static_cast<std::size_t>(lo < 0.0 && hi > 0.0 ? std::max(maxTicks, 3) : maxTicks)) << lo << ".." << hi;
    EXPECT_GE(t.values.size(), 2u);
    EXPECT_LE(t.lo, lo + 1e-9 * scale);
    EXPECT_GE(t.hi, hi - 1e-9 * scale);
    for (std::size_t k = 1; k < t.labels.size(); ++k) {
      EXPECT_EQ(t.labels[k].find('.') == std::string::npos, t.labels[0].find('.') == std::string::npos);
      EXPECT_NE(t.labels[k], t.labels[k - 1]) << "two ticks with one label: " << t.labels[k];
    }
  }
}

}  // namespace
}  // namespace rbsim::render
