#include "run/paths.h"

#include <cstdlib>

#include "render/data_dir.h"

namespace rbsim::app {

std::string assetDir() {
  if (const char* env = std::getenv("RBSIM_ASSET_DIR"); env && *env) return env;
  if (std::string beside = render::besideExecutable("assets"); !beside.empty()) return beside;
  return RBSIM_DEFAULT_ASSET_DIR;
}

}  // namespace rbsim::app
