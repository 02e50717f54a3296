#include "rbsim/math/format_number.h"

#include <sstream>

namespace rbsim {

std::string formatNumber(double d) {
  std::ostringstream out;
  out << d;
  return out.str();
}

}  // namespace rbsim
