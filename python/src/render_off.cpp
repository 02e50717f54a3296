// The physics-only module (RBSIM_PYTHON_RENDER=OFF, python/CMakeLists.txt): in place of
// py_render.cpp, binds no Renderer and no VideoWriter, so the module links no GL, LLVM, image or
// video library; rbsim/__init__.py says why rbsim.Renderer is missing when asked for it.
#include <pybind11/pybind11.h>

namespace rbsim::python {

void bindRendering(pybind11::module_& /*m*/) {}

}  // namespace rbsim::python
