#include "depth_capture.h"

#include <cstddef>
#include <string>

#include "projection.h"
#include "render_error.h"

namespace rbsim::render {

DepthCapture::DepthCapture(int width, int height) : width_(width), height_(height) {
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
  glDrawBuffer(GL_NONE);  // depth only
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &depth_);
    throw RenderError("OpenGL: the depth image's framebuffer is incomplete (status " + std::to_string(status) + ")");
  }
}

DepthCapture::~DepthCapture() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
}

void DepthCapture::clear() {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void DepthCapture::capture(GLuint source, const PaneRect& pane, int imageHeight) {
  // GL counts rows from the bottom; the pane, from the top. The blit obeys the scissor, which the
  // caller has on the pane anyway.
  const GLint y = imageHeight - pane.y - pane.height;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glBlitFramebuffer(pane.x, y, pane.x + pane.width, y + pane.height, pane.x, y, pane.x + pane.width, y + pane.height,
                    GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, source);
}

void DepthCapture::readMetres(float nearPlane, float farPlane, std::vector<float>& out) {
  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);
  window_.resize(w * h);
  out.resize(w * h);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  // As 32-bit integers, not floats: a float near 1 rounds the 24-bit value by up to half its step,
  // which would add to the buffer's own quantisation error.
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, window_.data());
  constexpr double kFullScale = 4294967295.0;  // 2^32 - 1: GL's unsigned normalised depth 1
  // Flipped while converting: one pass over the image either way.
  for (std::size_t row = 0; row < h; ++row) {
    const std::uint32_t* from = window_.data() + (h - 1 - row) * w;
    float* to = out.data() + row * w;
    for (std::size_t col = 0; col < w; ++col) to[col] = linearDepth(from[col] / kFullScale, nearPlane, farPlane);
  }
}

}  // namespace rbsim::render
