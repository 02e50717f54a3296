#pragma once
// Where rbsim's data folders (shaders/, assets/) are when rbsim runs from somewhere other than its
// build tree: beside the executable (an unpacked submission bundle: rbsim, shaders/, assets/) or
// in <prefix>/share/rbsim/ (an install: <prefix>/bin/rbsim, or the Python package rbsim/ in
// <prefix>/lib/python3.X/site-packages, a venv's, or <prefix>/lib/python3/dist-packages). No GL
// here: the physics-only Python module (RBSIM_PYTHON_RENDER=OFF) uses it too.
#include <string>

namespace rbsim::render {

// The first existing folder of <exe dir>/<name> and <exe dir>/../share/rbsim/<name> (the
// executable found through /proc/self/exe), then, for the Python module rbsim/_rbsim*.so,
// <module dir>/../../../../share/rbsim/<name>; empty when none exists.
std::string besideExecutable(const std::string& name);

// The shader folder: env RBSIM_SHADER_DIR if set, else shaders/ beside the executable (a bundle or
// an install, above), else the source tree's shaders/ baked in at build time.
std::string defaultShaderDir();

}  // namespace rbsim::render
