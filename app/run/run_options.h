#pragma once
// What the command line asks of one run, after CLI11 has parsed it. Scene keys are not here:
// flags such as --dt become `--set` assignments (cli/flags_to_overrides) so there is one path.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/gl_context.h"
#include "render/png_file.h"

namespace rbsim::app {

struct RunOptions {
  std::vector<std::string> overrides;  // "path=value" scene assignments, in order
  std::string framesDir;               // write PNG frames here when non-empty
  std::string videoPath;               // write an MP4 here when non-empty
  std::string tracePath;               // write the CSV trace here when non-empty
  std::uint64_t traceEvery = 1;        // trace every K-th step
  std::string recordPath;              // record every step's state here when non-empty (record/recording.h)
  std::string gltfPath;                // write the bodies and their motion as glTF 2.0 here when non-empty (export/)
  int pngLevel = render::kDefaultPngLevel;  // zlib level of the PNG frames, [0, 9]
  render::GlBackend glBackend = render::defaultGlBackend();  // --gl osmesa|egl
  bool render = true;                  // --no-render turns frames and video off
  bool quiet = false;
};

}  // namespace rbsim::app
