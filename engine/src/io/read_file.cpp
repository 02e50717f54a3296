#include "io/read_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rbsim/io/input_error.h"

namespace rbsim {

namespace {

constexpr double kBytesPerMegabyte = 1024.0 * 1024.0;
// Read in pieces so that a file growing past the limit stops the read at the limit.
constexpr std::size_t kReadChunkBytes = 1 << 20;  // [bytes]

std::string notRegular(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::fifo: return "is a FIFO (named pipe)";
    case std::filesystem::file_type::character: return "is a character device";
    case std::filesystem::file_type::block: return "is a block device";
    case std::filesystem::file_type::socket: return "is a socket";
    default: return "is not a regular file";
  }
}

}  // namespace

std::string describeBytes(std::uintmax_t bytes) {
  std::ostringstream out;
  out << bytes << " bytes (" << static_cast<std::uintmax_t>(bytes / kBytesPerMegabyte + 0.5) << " MB)";
  return out.str();
}

std::string readTextFile(const std::string& path, std::uintmax_t limitBytes, const std::string& field,
                         const std::string& kind) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || status.type() == std::filesystem::file_type::not_found) {
    throw InputError(path, field, "cannot open the file (missing or unreadable)");
  }
  if (status.type() == std::filesystem::file_type::directory) {
    throw InputError(path, field, "is a folder; expected " + kind);
  }
  if (status.type() != std::filesystem::file_type::regular) {
    throw InputError(path, field, notRegular(status.type()) + ", not a regular file; expected " + kind);
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  const std::string limit = "; the limit for " + kind + " is " + describeBytes(limitBytes);
  if (!ec && size > limitBytes) throw InputError(path, field, "is " + describeBytes(size) + limit);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, field, "cannot open the file (missing or unreadable)");
  std::string text;
  std::string chunk(kReadChunkBytes, '\0');
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > limitBytes) {
      throw InputError(path, field, "holds more than " + describeBytes(limitBytes) + " (it grew while being read)" + limit);
    }
  }
  if (in.bad()) throw InputError(path, field, "could not be read to the end (a read error)");
  return text;
}

}  // namespace rbsim
