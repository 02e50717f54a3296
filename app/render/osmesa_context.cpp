#include "osmesa_context.h"

#include <string>

#include "gl_api.h"
#include "render_error.h"

namespace rbsim::render {

OsmesaContext::OsmesaContext(int width, int height) : GlContext(width, height) {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_STENCIL_BITS,
                         8,
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
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(context_);
    throw RenderError("OSMesa: could not bind a " + std::to_string(width) + "x" +
                      std::to_string(height) + " RGBA8 buffer (too large for this driver?)");
  }
}

OsmesaContext::~OsmesaContext() {
  if (isCurrent()) {
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    clearCurrent();
  }
  OSMesaDestroyContext(context_);
}

void OsmesaContext::makeCurrent() {
  if (isCurrent()) return;
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width(), height())) {
    throw RenderError("OSMesa: could not make the context current");
  }
  markCurrent();
}

}  // namespace rbsim::render
