#pragma once
// Where rbsim's data folders (shaders/, assets/) are when rbsim runs from somewhere other than its
// build tree: beside the executable (an unpacked submission bundle: rbsim, shaders/, assets/) or
// in <prefix>/share/rbsim/ (an install: <prefix>/bin/rbsim, or the Python module in
// <prefix>/lib/python3/dist-packages or a venv's site-packages).
#include <string>

namespace rbsim::render {

// The first existing folder of <exe dir>/<name> and <exe dir>/../share/rbsim/<name> (the
// executable found through /proc/self/exe), then, for the Python module, <module dir>/../../../
// share/rbsim/<name>; empty when none exists.
std::string besideExecutable(const std::string& name);

}  // namespace rbsim::render
