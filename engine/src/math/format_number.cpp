#include "rbsim/math/format_number.h"

#include <sstream>

namespace rbsim {

std::string formatNumber(double d) {
  std::ostringstream out;
  out << d;
  return out.str();
}

std::string formatPastLimit(double value, double limit) {
  // 6: formatNumber's own precision (std::ostream's default); 17 round-trips any double.
  constexpr int kDefaultDigits = 6, kRoundTripDigits = 17;
  const auto at = [](double d, int digits) {
    std::ostringstream out;
    out.precision(digits);
    out << d;
    return out.str();
  };
  for (int digits = kDefaultDigits; digits < kRoundTripDigits; ++digits) {
    if (at(value, digits) != at(limit, digits)) return at(value, digits);
  }
  return at(value, kRoundTripDigits);
}

}  // namespace rbsim
