#pragma once
// The CSV trace of DESIGN.md ("Trace format"): one row per body per traced step, SI units,
// world frame, full double precision so external checks can reproduce our numbers.
#include <cstdint>
#include <fstream>
#include <string>

#include "world/world.h"

namespace rbsim::app {

class TraceWriter {
 public:
  explicit TraceWriter(const std::string& path);  // throws InputError if it cannot be written
  // `bodyPrefix` goes before every body name: "K/" for world K of a compared phase (phase.h).
  void write(const World& world, std::uint64_t globalStep, double time, const std::string& bodyPrefix = "");

 private:
  std::ofstream out_;
};

}  // namespace rbsim::app
