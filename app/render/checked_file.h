#pragma once
// A file written through stdio that keeps the first failure with the OS's reason: a short
// fwrite, a failed fflush and a failed fclose all count, because a buffered write to a full disk
// (or to /dev/full) only fails when the buffer is flushed, often at close.
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

  // Opens (truncating) for binary writing; false with error() set on failure.
  bool open(const std::filesystem::path& path);
  // Writes all `size` bytes; false with error() set on failure (or after an earlier failure).
  bool write(const void* data, std::size_t size);
  bool write(const std::string& text) { return write(text.data(), text.size()); }
  // Flushes and closes; false with error() set if anything written so far was lost.
  bool close();
  bool isOpen() const { return file_ != nullptr; }
  // The OS's words for the first failure (strerror), empty while all is well.
  const std::string& error() const { return error_; }

 private:
  bool fail(int errorNumber);

  std::FILE* file_ = nullptr;
  std::string error_;
};

}  // namespace rbsim::render
