#pragma once
// Numbers in messages: six significant digits in %g style, without trailing zeros (std::to_string
// prints 1e-7 as "0.000000" and 1e300 as 301 digits).
#include <string>

namespace rbsim {

std::string formatNumber(double d);

// `value` as formatNumber prints it, with as many more significant digits (up to the 17 that
// round-trip a double) as tell it apart from `limit` printed alike: 1000000.03 against 1e6 reads
// "1000000.03", not "1e+06" (issue 56, item 8). For messages that a value is past a limit.
std::string formatPastLimit(double value, double limit);

}  // namespace rbsim
