// The physics-only module (RBSIM_PYTHON_RENDER=OFF, python/CMakeLists.txt): in place of
// py_render.cpp and run_bindings.cpp, binds no Renderer, VideoWriter, World.run or rbsim.run (the
// program's runner, which draws frames), so the module links no GL, LLVM, image or
// video library; rbsim/__init__.py says why rbsim.Renderer is missing when asked for it.
#include <pybind11/pybind11.h>

#include "py_world.h"

namespace rbsim::python {

void bindRendering(pybind11::module_& /*m*/) {}
void bindRun(pybind11::module_& /*m*/, pybind11::class_<PyWorld>& /*world*/) {}

}  // namespace rbsim::python
