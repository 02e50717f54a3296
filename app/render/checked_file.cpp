#include "checked_file.h"

#include <cerrno>
#include <cstring>
#include <system_error>

namespace rbsim::render {

CheckedFile::~CheckedFile() {
  if (file_) std::fclose(file_);
  discard();
}

void CheckedFile::discard() {
  if (!writing_.empty() && writing_ != final_) {
    std::error_code ignored;  // nothing more to tell: the failure that brought us here is kept
    std::filesystem::remove(writing_, ignored);
  }
  writing_.clear();
  final_.clear();
}

bool CheckedFile::fail(int errorNumber) {
  // errno 0 would print "Success": stdio failed without saying why (it should not happen).
  if (error_.empty()) error_ = errorNumber != 0 ? std::strerror(errorNumber) : "unknown write error";
  return false;
}

bool CheckedFile::open(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  const bool special = !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
  final_ = path;
  writing_ = special ? path : std::filesystem::path(path.string() + ".partial");
  errno = 0;
  file_ = std::fopen(writing_.string().c_str(), "wb");
  if (file_) return true;
  const int why = errno;
  writing_.clear();  // nothing was made to remove
  final_.clear();
  return fail(why);
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
  if (!flushed || !closed || !error_.empty()) {
    discard();
    return !flushed ? fail(flushErrno) : !closed ? fail(closeErrno) : false;
  }
  if (writing_ != final_) {
    std::error_code ec;
    std::filesystem::rename(writing_, final_, ec);  // atomic within one folder (POSIX rename)
    if (ec) {
      discard();
      return fail(ec.value());
    }
  }
  writing_.clear();
  final_.clear();
  return true;
}

}  // namespace rbsim::render
