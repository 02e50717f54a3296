#pragma once
// Numbers in messages: six significant digits in %g style, without trailing zeros (std::to_string
// prints 1e-7 as "0.000000" and 1e300 as 301 digits).
#include <string>

namespace rbsim {

std::string formatNumber(double d);

}  // namespace rbsim
