#pragma once
// An EGL context on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless, no window
// system, no device): OpenGL 4.5 compatibility profile on llvmpipe, drawing into a framebuffer
// object of its own, read back with glReadPixels. The successor of OSMesa for off-screen
// rendering (OSMesa is gone from Mesa 25.1 on).
#include <cstdint>
#include <vector>

#include "gl_context.h"

namespace rbsim::render {

class EglContext final : public GlContext {
 public:
  // Throws RenderError naming the EGL call and its error code when the display, the context or
  // the framebuffer cannot be made.
  EglContext(int width, int height);
  ~EglContext() override;

  void makeCurrent() override;
  unsigned framebuffer() const override { return fbo_; }
  const std::uint8_t* pixels() override;

 private:
  void* display_ = nullptr;  // EGLDisplay, kept opaque so EGL headers stay in the .cpp
  void* context_ = nullptr;  // EGLContext
  unsigned fbo_ = 0, colorRb_ = 0, depthRb_ = 0;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace rbsim::render
