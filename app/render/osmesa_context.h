#pragma once
// An OSMesa (llvmpipe) OpenGL 4.5 compatibility-profile context. It draws into its framebuffer
// object (gl_context.h); OSMesa's own buffer is one pixel, made only because OSMesa cannot make a
// context current without one. Compatibility rather than core because ImGui's OpenGL2 backend (the only Debian
// backend that starts under OSMesa, see docs/architecture.md, "Rendering facts") uses fixed-function calls; GLSL 4.50 shaders
// run in the same context.
#include <cstdint>

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

 private:
  std::uint8_t windowPixel_[4] = {};  // OSMesa's own buffer, never drawn into
  OSMesaContext context_ = nullptr;
};

}  // namespace rbsim::render
