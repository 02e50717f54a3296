#pragma once
// Where rbsim finds its data at run time: the source tree it was built from (baked in at build
// time), unless RBSIM_ASSET_DIR points elsewhere.
#include <string>

namespace rbsim::app {

std::string assetDir();  // .../assets

}  // namespace rbsim::app
