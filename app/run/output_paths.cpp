#include "run/output_paths.h"

#include <sys/stat.h>

#include <filesystem>

#include "rbsim/io/input_error.h"

namespace rbsim::app {

namespace {

namespace fs = std::filesystem;

std::string describeType(fs::file_type type) {
  switch (type) {
    case fs::file_type::fifo: return "a FIFO (named pipe)";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::socket: return "a socket";
    case fs::file_type::directory: return "a folder";
    case fs::file_type::regular: return "a file";
    default: return "not a regular file";
  }
}

// The path a writer will end up at: absolute, symlinks of its existing part resolved, "." and
// ".." taken out. "sub/../s.json" names s.json even while sub does not exist (the kernel would not
// find it, but the trace writer makes sub first). Absolute first: libstdc++'s weakly_canonical
// leaves "r.bin" relative and makes "./r.bin" absolute when neither exists.
fs::path resolved(const std::string& p) {
  std::error_code ec;
  fs::path out = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::path(p).lexically_normal() : out;
}

// Whether a and b are one file: the same device and inode when both exist (a hard link, a
// symlink), else the same resolved path (a file not created yet has no inode).
bool sameFile(const std::string& a, const std::string& b) {
  const fs::path ra = resolved(a), rb = resolved(b);
  struct stat sa {}, sb {};
  if (::stat(ra.c_str(), &sa) == 0 && ::stat(rb.c_str(), &sb) == 0) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  return ra == rb;
}

std::string named(const NamedFile& f) { return f.role + " " + f.path; }

}  // namespace

std::size_t removeOldFrames(const std::string& framesDir) {
  std::error_code ec;
  std::size_t removed = 0;
  for (fs::directory_iterator it(framesDir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    // frame_ and at least six digits (more past a million frames), then .png.
    const bool ours = name.size() >= 16 && name.compare(0, 6, "frame_") == 0 &&
                      name.compare(name.size() - 4, 4, ".png") == 0 && name.find_first_not_of("0123456789", 6) == name.size() - 4;
    std::error_code typeError;
    if (ours && it->is_regular_file(typeError) && fs::remove(it->path(), typeError)) ++removed;
  }
  return removed;
}

void requireRegularInput(const NamedFile& input, const std::string& kind) {
  std::error_code ec;
  const fs::file_status status = fs::status(input.path, ec);
  if (ec || status.type() == fs::file_type::not_found) {
    throw InputError(input.path, "", "cannot open the file (missing or unreadable); expected " + kind);
  }
  if (status.type() != fs::file_type::regular) {
    throw InputError(input.path, "", "is " + describeType(status.type()) + ", not a regular file; expected " + kind);
  }
}

void checkOutputPaths(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs,
                      const std::string& framesDir) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedFile& out = outputs[i];
    std::error_code ec;
    const fs::file_status status = fs::status(resolved(out.path), ec);
    if (!ec && status.type() != fs::file_type::not_found && status.type() != fs::file_type::regular) {
      throw InputError("", named(out), "is " + describeType(status.type()) + "; expected a regular file to write, or a new name");
    }
    for (const NamedFile& in : inputs) {
      if (sameFile(out.path, in.path)) {
        throw InputError("", named(out), "is the " + in.role + " " + in.path + " being read; writing it would destroy it: give the output another name");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (sameFile(out.path, outputs[j].path)) {
        throw InputError("", named(out), "is also " + named(outputs[j]) + "; one would overwrite the other: give them different names");
      }
    }
  }
  if (!framesDir.empty()) {
    std::error_code ec;
    const fs::file_status status = fs::status(framesDir, ec);
    if (!ec && status.type() != fs::file_type::not_found && status.type() != fs::file_type::directory) {
      throw InputError("", "--frames " + framesDir, "is " + describeType(status.type()) + ", not a folder; expected a folder (made if missing)");
    }
  }
}

}  // namespace rbsim::app
