#include "gl_context.h"

#include <cstring>

#include "egl_context.h"
#include "gl_api.h"
#include "render_error.h"
#ifdef RBSIM_HAVE_OSMESA
#include "osmesa_context.h"
#endif

namespace rbsim::render {

namespace {
thread_local const GlContext* currentContext = nullptr;
}  // namespace

bool GlContext::isCurrent() const { return currentContext == this; }
void GlContext::markCurrent() const { currentContext = this; }
void GlContext::clearCurrent() const {
  if (currentContext == this) currentContext = nullptr;
}

void GlContext::createFramebuffer(const char* backend) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  const std::string size = std::to_string(width_) + "x" + std::to_string(height_);
  if (width_ > maxSize || height_ > maxSize) {
    throw RenderError(std::string(backend) + ": image size " + size + " is over the driver's largest framebuffer, " +
                      std::to_string(maxSize));
  }
  glGenRenderbuffers(1, &colorRb_);
  glBindRenderbuffer(GL_RENDERBUFFER, colorRb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  glGenRenderbuffers(1, &depthRb_);
  glBindRenderbuffer(GL_RENDERBUFFER, depthRb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width_, height_);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorRb_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthRb_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    deleteFramebuffer();
    throw RenderError(std::string(backend) + ": the " + size + " framebuffer object is incomplete (status " +
                      std::to_string(status) + "; out of memory?)");
  }
  GLint extensions = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &extensions);
  for (GLint k = 0; k < extensions && !packInvert_; ++k) {
    const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(k)));
    packInvert_ = name != nullptr && std::string(name) == "GL_MESA_pack_invert";
  }
  if (!packInvert_) buffer_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4, 0);
}

void GlContext::deleteFramebuffer() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colorRb_);
  glDeleteRenderbuffers(1, &depthRb_);
  fbo_ = colorRb_ = depthRb_ = 0;
}

void GlContext::readTopDown(std::uint8_t* out) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  if (packInvert_) {
    glPixelStorei(GL_PACK_INVERT_MESA, GL_TRUE);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out);
    glPixelStorei(GL_PACK_INVERT_MESA, GL_FALSE);
    return;
  }
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, buffer_.data());
  const std::size_t rowBytes = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    std::memcpy(out + static_cast<std::size_t>(y) * rowBytes,
                buffer_.data() + static_cast<std::size_t>(height_ - 1 - y) * rowBytes, rowBytes);
  }
}

GlBackend defaultGlBackend() {
#ifdef RBSIM_HAVE_OSMESA
  return GlBackend::Osmesa;
#else
  return GlBackend::Egl;
#endif
}

std::optional<GlBackend> parseGlBackend(const std::string& name) {
#ifdef RBSIM_HAVE_OSMESA
  if (name == "osmesa") return GlBackend::Osmesa;
#endif
  if (name == "egl") return GlBackend::Egl;
  return std::nullopt;
}

const char* glBackendName(GlBackend backend) {
  return backend == GlBackend::Osmesa ? "osmesa" : "egl";
}

std::string glBackendChoices() {
#ifdef RBSIM_HAVE_OSMESA
  return "osmesa|egl";
#else
  return "egl (this build has no OSMesa)";
#endif
}

std::unique_ptr<GlContext> makeGlContext(GlBackend backend, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw RenderError(std::string(glBackendName(backend)) + ": invalid image size " +
                      std::to_string(width) + "x" + std::to_string(height));
  }
#ifdef RBSIM_HAVE_OSMESA
  if (backend == GlBackend::Osmesa) return std::make_unique<OsmesaContext>(width, height);
#endif
  if (backend == GlBackend::Egl) return std::make_unique<EglContext>(width, height);
  throw RenderError(std::string("this build has no ") + glBackendName(backend) + " context");
}

}  // namespace rbsim::render
