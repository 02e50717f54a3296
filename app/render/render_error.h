#pragma once
// The one exception type of the renderer and frame output, so the app can map every rendering or
// encoding failure (no GL context, missing shader, unwritable folder, ffmpeg missing or failing)
// to a single clear message and exit code.
#include <stdexcept>
#include <string>

namespace rbsim::render {

class RenderError : public std::runtime_error {
 public:
  explicit RenderError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rbsim::render
