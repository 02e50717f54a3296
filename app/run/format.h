#pragma once
// printf-style formatting of one or two numbers into a string, for the overlay's rows.
#include <cstdio>
#include <string>

namespace rbsim::app {

inline std::string format(const char* pattern, double a, double b = 0.0) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, pattern, a, b);
  return buffer;
}

}  // namespace rbsim::app
