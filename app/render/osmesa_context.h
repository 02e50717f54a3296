#pragma once
// An OSMesa (llvmpipe) OpenGL 4.5 compatibility-profile context that renders into a buffer in
// main memory. Compatibility rather than core because ImGui's OpenGL2 backend (the only Debian
// backend that starts under OSMesa, see DESIGN.md) uses fixed-function calls; GLSL 4.50 shaders
// run in the same context.
#include <cstdint>
#include <vector>

#include <GL/osmesa.h>

namespace rbsim::render {

class OsmesaContext {
 public:
  // Creates the context with an RGBA8 colour buffer of width x height, 24-bit depth and 8-bit
  // stencil, and makes it current on this thread. Throws RenderError if that is impossible.
  OsmesaContext(int width, int height);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  // Makes the context current on the calling thread (cheap when it already is).
  void makeCurrent();

  int width() const { return width_; }
  int height() const { return height_; }
  // The colour buffer, RGBA8, bottom row first (GL's origin); valid after glFinish().
  const std::uint8_t* pixels() const { return buffer_.data(); }

 private:
  int width_;
  int height_;
  std::vector<std::uint8_t> buffer_;
  OSMesaContext context_ = nullptr;
};

}  // namespace rbsim::render
