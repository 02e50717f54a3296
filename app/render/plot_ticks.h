#pragma once
// Readable axis ticks (issue 38): steps of 1, 2 or 5 times a power of ten, the axis widened to
// whole steps, and labels sharing one power of ten when the numbers are very large or small
// (Heckbert, "Nice numbers for graph labels", Graphics Gems, 1990).
#include <string>
#include <vector>

namespace rbsim::render {

struct AxisTicks {
  double lo = 0.0, hi = 1.0;        // the axis, widened to whole steps
  double step = 1.0;
  std::vector<double> values;       // lo, lo + step, ..., hi
  int exponent = 0;                 // labels are value / 10^exponent (0: as they are)
  std::vector<std::string> labels;  // the same precision for every tick
};

// Ticks for data in [lo, hi] with at most maxTicks of them (at least 2; 3 for data on both sides
// of zero). `nonNegative`: the axis
// does not go below 0 (a length, a count, an energy of motion).
AxisTicks niceTicks(double lo, double hi, int maxTicks, bool nonNegative);

// " [x1e-3 J]" for a shared exponent, " [J]" without one, "" for neither.
std::string axisUnit(const AxisTicks& ticks, const std::string& unit);

}  // namespace rbsim::render
