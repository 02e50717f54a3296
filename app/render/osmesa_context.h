#pragma once
// An OSMesa (llvmpipe) OpenGL 4.5 compatibility-profile context that renders into a buffer in
// main memory. Compatibility rather than core because ImGui's OpenGL2 backend (the only Debian
// backend that starts under OSMesa, see DESIGN.md) uses fixed-function calls; GLSL 4.50 shaders
// run in the same context.
#include <cstdint>
#include <vector>

#include <GL/osmesa.h>

#include "gl_context.h"

namespace rbsim::render {

class OsmesaContext final : public GlContext {
 public:
  // Creates the context with an RGBA8 colour buffer of width x height, 24-bit depth and 8-bit
  // stencil, and makes it current on this thread. Throws RenderError if that is impossible.
  OsmesaContext(int width, int height);
  ~OsmesaContext() override;

  void makeCurrent() override;
  unsigned framebuffer() const override { return 0; }
  // OSMesa renders straight into this buffer: nothing to read back.
  const std::uint8_t* pixels() override { return buffer_.data(); }

 private:
  std::vector<std::uint8_t> buffer_;
  OSMesaContext context_ = nullptr;
};

}  // namespace rbsim::render
