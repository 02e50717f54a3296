// Fuzz target: the recording reader (record/recording.h, issue 37) on arbitrary bytes, replayed
// against one fixed small scene (a ball and a box over a plane, 10 steps), as `rbsim replay`
// would: the magic, the version, the header and its checksum, the blocks, the entries and their
// validation, the end marker. Only InputError may come out; anything else, a crash, a sanitizer
// report or memory past libFuzzer's limit is a bug.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "rbsim/io/input_error.h"
#include "record/recording.h"
#include "run/phase.h"
#include "run/runner.h"

namespace {

constexpr const char* kScene =
    R"({"world": {"dt": 0.01, "steps": 10}, "planes": [{"normal": [0, 1, 0]}],
        "bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, "mass": 1, "position": [0, 1, 0]},
                   {"name": "box", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 2, "position": [2, 0.6, 0]}]})";

const std::vector<rbsim::app::Phase>& phases() {
  static const std::vector<rbsim::app::Phase> p{rbsim::app::parsePhaseText(kScene, "fuzz.json", "")};
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The reader reads a file: the input goes to one of this process's own.
  static const std::string path = "/tmp/rbsim_record_fuzz_" + std::to_string(::getpid()) + ".rbrec";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    rbsim::app::RecordReader reader(path);
    rbsim::app::RunOptions options;
    options.quiet = true;
    options.render = false;
    rbsim::app::runPhases(phases(), options, "fuzz", {}, &reader);
  } catch (const rbsim::InputError&) {
  }
  std::remove(path.c_str());
  return 0;
}
