#include "render/data_dir.h"

#include <dlfcn.h>

#include <cstdlib>

#include <filesystem>
#include <system_error>
#include <vector>

namespace rbsim::render {

namespace {

// The file this code was loaded from: the rbsim program, or the Python module (a shared object
// inside python3, whose /proc/self/exe is the interpreter).
std::filesystem::path loadedFrom() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&besideExecutable), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code error;
  const std::filesystem::path path = std::filesystem::canonical(info.dli_fname, error);
  return error ? std::filesystem::path() : path;
}

}  // namespace

std::string besideExecutable(const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code error;
  std::vector<fs::path> candidates;
  // The program: <dir>/name (an unpacked bundle), <prefix>/bin -> <prefix>/share/rbsim.
  if (const fs::path exe = fs::read_symlink("/proc/self/exe", error); !error) {
    candidates.push_back(exe.parent_path() / name);
    candidates.push_back(exe.parent_path() / ".." / "share" / "rbsim" / name);
  }
  // The Python module, <site>/rbsim/_rbsim*.so, where <site> is <prefix>/lib/python3.X/site-packages
  // (cmake --install, a venv's pip install), <prefix>/lib/python3.X/dist-packages or
  // <prefix>/lib/python3/dist-packages (Debian's /usr/local and /usr): four folders below
  // <prefix>/share/rbsim.
  if (const fs::path module = loadedFrom(); !module.empty() && module.extension() == ".so") {
    candidates.push_back(module.parent_path() / ".." / ".." / ".." / ".." / "share" / "rbsim" / name);
  }
  for (const fs::path& candidate : candidates) {
    if (fs::is_directory(candidate, error)) return fs::weakly_canonical(candidate, error).string();
  }
  return {};
}

std::string defaultShaderDir() {
  if (const char* dir = std::getenv("RBSIM_SHADER_DIR"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  if (std::string beside = besideExecutable("shaders"); !beside.empty()) return beside;
  return RBSIM_DEFAULT_SHADER_DIR;
}

}  // namespace rbsim::render
