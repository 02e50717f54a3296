#include "egl_context.h"

#include <cstdio>
#include <string>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gl_api.h"
#include "render_error.h"

namespace rbsim::render {

namespace {

[[noreturn]] void fail(const std::string& what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  throw RenderError("EGL: " + what + " failed (error " + code +
                    "; needs Mesa's libegl-mesa0 with the surfaceless platform)");
}

// The surfaceless display, initialised once per process and never terminated: eglTerminate
// would end every context on it, and EGL keeps one display per platform anyway.
EGLDisplay surfacelessDisplay() {
  static const EGLDisplay display = [] {
    const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (extensions == nullptr || std::string(extensions).find("EGL_MESA_platform_surfaceless") == std::string::npos) {
      throw RenderError("EGL: the surfaceless platform (EGL_MESA_platform_surfaceless) is not offered");
    }
    const auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay == nullptr) fail("eglGetProcAddress(eglGetPlatformDisplayEXT)");
    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT(surfaceless)");
    EGLint major = 0, minor = 0;
    if (eglInitialize(d, &major, &minor) != EGL_TRUE) fail("eglInitialize");
    return d;
  }();
  return display;
}

}  // namespace

EglContext::EglContext(int width, int height) : GlContext(width, height) {
  EGLDisplay display = surfacelessDisplay();
  display_ = display;
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) fail("eglBindAPI(OpenGL)");
  // No config and no surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): the
  // image lives in the framebuffer object.
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                            EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                            EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context == EGL_NO_CONTEXT) fail("eglCreateContext(OpenGL 4.5 compatibility)");
  context_ = context;
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    eglDestroyContext(display, context);
    fail("eglMakeCurrent");
  }
  markCurrent();
  try {
    createFramebuffer("EGL");
  } catch (...) {
    release();
    throw;
  }
}

EglContext::~EglContext() {
  makeCurrent();
  deleteFramebuffer();
  release();
}

void EglContext::release() {
  const auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  clearCurrent();
  eglDestroyContext(display, static_cast<EGLContext>(context_));
}

void EglContext::makeCurrent() {
  if (isCurrent()) return;
  // EGL keeps its own idea of what is current and skips a switch to that context, even after an
  // OSMesa context took over the shared dispatch: release first so the switch happens.
  if (eglGetCurrentContext() == static_cast<EGLContext>(context_)) {
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                     static_cast<EGLContext>(context_)) != EGL_TRUE) {
    fail("eglMakeCurrent");
  }
  markCurrent();
}

}  // namespace rbsim::render
