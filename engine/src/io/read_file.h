#pragma once
// Reading a whole input file into memory, refused before reading when it cannot be a sane input:
// a folder, a FIFO, a device or a socket (/dev/zero, a named pipe: endless or blocking), or a
// regular file larger than the caller's limit (which would otherwise be read until memory runs out).
#include <cstdint>
#include <string>

namespace rbsim {

// The text of the regular file at `path`, at most `limitBytes` long. `field` names the input in
// the InputError (e.g. "mesh"), `kind` says what was expected (e.g. "an OBJ file"). Throws
// InputError(path, field, ...) for a missing or unreadable file, anything but a regular file, or a
// file over the limit (checked on its size before reading and again while reading, since a file
// may grow or, like /proc files, report no size).
std::string readTextFile(const std::string& path, std::uintmax_t limitBytes, const std::string& field,
                         const std::string& kind);

// "123456789 bytes (118 MB)": a byte count for messages.
std::string describeBytes(std::uintmax_t bytes);

}  // namespace rbsim
