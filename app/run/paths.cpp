#include "run/paths.h"

#include <cstdlib>

namespace rbsim::app {

std::string assetDir() {
  if (const char* env = std::getenv("RBSIM_ASSET_DIR"); env && *env) return env;
  return RBSIM_DEFAULT_ASSET_DIR;
}

}  // namespace rbsim::app
