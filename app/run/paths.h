#pragma once
// Where rbsim finds its data at run time: RBSIM_ASSET_DIR if set, else assets/ beside the
// executable (a bundle or an install, render/data_dir.h), else the source tree it was built from
// (baked in at build time).
#include <string>

namespace rbsim::app {

std::string assetDir();  // .../assets

}  // namespace rbsim::app
