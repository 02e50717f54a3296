#include "plot_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rbsim::render {

namespace {

// Labels of numbers at least this large, or this small, share a power of ten [1].
constexpr double kLargestPlain = 1e4;
constexpr double kSmallestPlain = 1e-2;
// A flat line (a conserved quantity) still gets an axis this wide, relative to its size, so that
// its rounding is not blown up to the plot's height [1]; and this wide when it is zero [the unit].
constexpr double kMinRelativeSpan = 2e-3;
constexpr double kZeroSpan = 1.0;

// The smallest of 1, 2, 5 times a power of ten at least x (x > 0).
double niceStep(double x) {
  const double power = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * power >= x * (1.0 - 1e-9)) return m * power;
  }
  return 10.0 * power;
}

}  // namespace

AxisTicks niceTicks(double lo, double hi, int maxTicks, bool nonNegative) {
  AxisTicks t;
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  const double span = magnitude > 0.0 ? std::max(hi - lo, kMinRelativeSpan * magnitude) : kZeroSpan;
  if (hi - lo < span) {
    const double middle = 0.5 * (lo + hi);
    lo = middle - 0.5 * span;
    hi = middle + 0.5 * span;
  }
  if (nonNegative && lo < 0.0) hi -= lo, lo = 0.0;  // the same span, from zero
  // Data on both sides of zero needs three ticks at whole steps (-s, 0, s) at the least.
  maxTicks = std::max(maxTicks, lo < 0.0 && hi > 0.0 ? 3 : 2);
  t.step = niceStep((hi - lo) / (maxTicks - 1));
  // Widening to whole steps can add a tick at each end: take the next step while there are too many.
  while (true) {
    t.lo = std::floor(lo / t.step + 1e-9) * t.step;
    t.hi = std::ceil(hi / t.step - 1e-9) * t.step;
    if (std::lround((t.hi - t.lo) / t.step) + 1 <= maxTicks) break;
    t.step = niceStep(t.step * 1.5);
  }
  const long count = std::lround((t.hi - t.lo) / t.step) + 1;
  for (long i = 0; i < count; ++i) {
    const double v = t.lo + static_cast<double>(i) * t.step;
    t.values.push_back(std::abs(v) < 1e-9 * t.step ? 0.0 : v);
  }
  const double largest = std::max(std::abs(t.lo), std::abs(t.hi));
  if (largest >= kLargestPlain || (largest > 0.0 && largest < kSmallestPlain)) {
    t.exponent = static_cast<int>(std::floor(std::log10(largest)));
  }
  const double scale = std::pow(10.0, -t.exponent);
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(t.step * scale) + 1e-9)));
  for (const double v : t.values) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, v * scale);
    t.labels.push_back(text);
  }
  return t;
}

std::string axisUnit(const AxisTicks& ticks, const std::string& unit) {
  if (ticks.exponent == 0) return unit.empty() ? "" : " [" + unit + "]";
  return " [x1e" + std::to_string(ticks.exponent) + (unit.empty() ? "" : " " + unit) + "]";
}

}  // namespace rbsim::render
