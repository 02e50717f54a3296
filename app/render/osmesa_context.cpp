#include "osmesa_context.h"

#include <string>

#include "gl_api.h"
#include "render_error.h"

namespace rbsim::render {

OsmesaContext::OsmesaContext(int width, int height) : GlContext(width, height) {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_STENCIL_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_COMPAT_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         4,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         5,
                         0};
  context_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (context_ == nullptr) {
    throw RenderError(
        "OSMesa: could not create an OpenGL 4.5 compatibility-profile context "
        "(is libosmesa6 from Mesa >= 20 with llvmpipe installed?)");
  }
  if (!OSMesaMakeCurrent(context_, windowPixel_, GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(context_);
    throw RenderError("OSMesa: could not make the context current");
  }
  markCurrent();
  try {
    createFramebuffer("OSMesa");
  } catch (...) {
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    clearCurrent();
    OSMesaDestroyContext(context_);
    throw;
  }
}

OsmesaContext::~OsmesaContext() {
  makeCurrent();
  deleteFramebuffer();
  OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  clearCurrent();
  OSMesaDestroyContext(context_);
}

void OsmesaContext::makeCurrent() {
  if (isCurrent()) return;
  if (!OSMesaMakeCurrent(context_, windowPixel_, GL_UNSIGNED_BYTE, 1, 1)) {
    throw RenderError("OSMesa: could not make the context current");
  }
  markCurrent();
}

}  // namespace rbsim::render
