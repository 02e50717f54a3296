#include "render/data_dir.h"

#include <filesystem>
#include <system_error>

namespace rbsim::render {

std::string besideExecutable(const std::string& name) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const fs::path dir = exe.parent_path();
  for (const fs::path& candidate : {dir / name, dir / ".." / "share" / "rbsim" / name}) {
    if (fs::is_directory(candidate, error)) return fs::weakly_canonical(candidate, error).string();
  }
  return {};
}

}  // namespace rbsim::render
