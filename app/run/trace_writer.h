#pragma once
// The CSV trace of docs/architecture.md ("Trace"): one row per body per traced step, SI units,
// world frame, full double precision so external checks can reproduce our numbers. Fields are
// quoted as RFC 4180 asks (a body name may hold a comma, a quote or a line break), and every
// write is checked: a full disk stops the run with the file and the OS's reason.
#include <cstdint>
#include <string>

#include "render/checked_file.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// `field` as one CSV field: unchanged unless it holds a comma, a double quote, CR or LF; then
// in double quotes with each quote doubled (RFC 4180).
std::string csvField(const std::string& field);

class TraceWriter {
 public:
  // Creates the folders above `path`; throws InputError (field --trace) if it cannot be written.
  explicit TraceWriter(const std::string& path);
  // `bodyPrefix` goes before every body name: "K/" for world K of a compared phase (phase.h).
  // Throws InputError naming the file and the OS's reason when a write fails.
  void write(const World& world, std::uint64_t globalStep, double time, const std::string& bodyPrefix = "");
  // Flushes and closes; throws InputError as write() does (a full disk often shows only here).
  void close();

 private:
  void put(const std::string& text);
  [[noreturn]] void fail() const;

  std::string path_;
  render::CheckedFile out_;
  std::string row_;  // reused for every row, so tracing allocates nothing per row
};

}  // namespace rbsim::app
