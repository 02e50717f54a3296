#pragma once
// An EGL context on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless, no window
// system, no device): OpenGL 4.5 compatibility profile on llvmpipe. The successor of OSMesa for
// off-screen rendering (OSMesa is gone from Mesa 25.1 on).
#include "gl_context.h"

namespace rbsim::render {

class EglContext final : public GlContext {
 public:
  // Throws RenderError naming the EGL call and its error code when the display, the context or
  // the framebuffer cannot be made.
  EglContext(int width, int height);
  ~EglContext() override;

  void makeCurrent() override;

 private:
  void release();  // no context current, this one destroyed

  void* display_ = nullptr;  // EGLDisplay, kept opaque so EGL headers stay in the .cpp
  void* context_ = nullptr;  // EGLContext
};

}  // namespace rbsim::render
