#pragma once
// A file written through stdio that keeps the first failure with the OS's reason: a short
// fwrite, a failed fflush and a failed fclose all count, because a buffered write to a full disk
// (or to /dev/full) only fails when the buffer is flushed, often at close.
// An output appears whole or not at all (issue 56): the bytes go to NAME.partial beside it, which
// a successful close() renames to NAME and a failure, or the object's end without close(),
// removes; a file NAME held before stays as it was until then. A destination that exists and is
// not a regular file (a device, a FIFO) is written in place.
#include <cstdio>
#include <filesystem>
#include <string>

namespace rbsim::render {

class CheckedFile {
 public:
  CheckedFile() = default;
  ~CheckedFile();  // closes without reporting; call close() to learn whether everything was written
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;

  // Opens path's partial file (truncating it) for binary writing; false with error() set on failure.
  bool open(const std::filesystem::path& path);
  // Writes all `size` bytes; false with error() set on failure (or after an earlier failure).
  bool write(const void* data, std::size_t size);
  bool write(const std::string& text) { return write(text.data(), text.size()); }
  // Flushes, closes and renames the partial file into place; false with error() set (and the
  // partial file removed) if anything written so far was lost.
  bool close();
  bool isOpen() const { return file_ != nullptr; }
  // The OS's words for the first failure (strerror), empty while all is well.
  const std::string& error() const { return error_; }

 private:
  bool fail(int errorNumber);
  void discard();  // removes the partial file, if there is one

  std::FILE* file_ = nullptr;
  std::filesystem::path writing_, final_;  // the file written and its name once complete
  std::string error_;
};

}  // namespace rbsim::render
