#include "checked_file.h"

#include <cerrno>
#include <cstring>

namespace rbsim::render {

CheckedFile::~CheckedFile() {
  if (file_) std::fclose(file_);
}

bool CheckedFile::fail(int errorNumber) {
  // errno 0 would print "Success": stdio failed without saying why (it should not happen).
  if (error_.empty()) error_ = errorNumber != 0 ? std::strerror(errorNumber) : "unknown write error";
  return false;
}

bool CheckedFile::open(const std::filesystem::path& path) {
  errno = 0;
  file_ = std::fopen(path.string().c_str(), "wb");
  return file_ ? true : fail(errno);
}

bool CheckedFile::write(const void* data, std::size_t size) {
  if (!file_ || !error_.empty()) return fail(EBADF);
  errno = 0;
  if (size > 0 && std::fwrite(data, 1, size, file_) != size) return fail(errno);
  return true;
}

bool CheckedFile::close() {
  if (!file_) return error_.empty() ? fail(EBADF) : false;
  errno = 0;
  const bool flushed = std::fflush(file_) == 0;
  const int flushErrno = errno;
  errno = 0;
  const bool closed = std::fclose(file_) == 0;
  const int closeErrno = errno;
  file_ = nullptr;
  if (!flushed) return fail(flushErrno);
  if (!closed) return fail(closeErrno);
  return error_.empty();
}

}  // namespace rbsim::render
