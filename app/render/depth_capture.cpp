#include "depth_capture.h"

#include <algorithm>
#include <cstddef>
#include <string>

#include "projection.h"
#include "render_error.h"

namespace rbsim::render {

void DepthCapture::makeTarget(int width, int height, int samples, GLuint& fbo, GLuint& depth) {
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);
  glDrawBuffer(GL_NONE);  // depth only
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    throw RenderError("OpenGL: the depth image's framebuffer is incomplete (status " + std::to_string(status) + ")");
  }
}

DepthCapture::DepthCapture(int width, int height, int samples) : width_(width), height_(height) {
  const int stored = samples > 1 ? samples : 0;  // as GlRenderer::createTarget stores them
  makeTarget(width, height, stored, fbo_, depth_);
  if (stored > 0) makeTarget(width, height, 0, resolvedFbo_, resolvedDepth_);
}

DepthCapture::~DepthCapture() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteFramebuffers(1, &resolvedFbo_);
  glDeleteRenderbuffers(1, &resolvedDepth_);
}

void DepthCapture::capture(GLuint source, const PaneRect& pane, int imageHeight) {
  glBindFramebuffer(GL_FRAMEBUFFER, source);
  GLint renderbuffer = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                        &renderbuffer);
  // GL counts rows from the bottom; the pane, from the top.
  const GLint y = imageHeight - pane.y - pane.height;
  glCopyImageSubData(static_cast<GLuint>(renderbuffer), GL_RENDERBUFFER, 0, pane.x, y, 0, depth_, GL_RENDERBUFFER, 0,
                     pane.x, y, 0, pane.width, pane.height, 1);
  panes_.push_back(pane);
}

void DepthCapture::readMetres(float nearPlane, float farPlane, std::vector<float>& out) {
  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);
  window_.resize(w * h);
  out.resize(w * h);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  if (resolvedFbo_ != 0) {
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolvedFbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolvedFbo_);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  // Depth and stencil packed as the buffer stores them (24-bit depth over 8-bit stencil): a memory
  // copy, where GL_DEPTH_COMPONENT converts each value; and the exact integer, where a float near 1
  // would round it by up to half a step.
  glReadPixels(0, 0, width_, height_, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, window_.data());
  constexpr int kStencilBits = 8;
  constexpr double kFullScale = 16777215.0;  // 2^24 - 1: the 24-bit depth 1
  const DepthLinearizer metres(nearPlane, farPlane);
  // Flipped while converting: one pass over the image either way.
  for (std::size_t row = 0; row < h; ++row) {
    const std::uint32_t* from = window_.data() + (h - 1 - row) * w;
    float* to = out.data() + row * w;
    for (std::size_t col = 0; col < w; ++col) {
      to[col] = metres((from[col] >> kStencilBits) / kFullScale);
    }
  }
  if (panes_.size() == 1 && panes_[0].x == 0 && panes_[0].y == 0 && panes_[0].width == width_ && panes_[0].height == height_) {
    return;  // one pane, the whole image
  }
  std::vector<bool> covered(w * h, false);
  for (const PaneRect& pane : panes_) {
    for (int row = pane.y; row < pane.y + pane.height; ++row) {
      const std::size_t first = static_cast<std::size_t>(row) * w + static_cast<std::size_t>(pane.x);
      std::fill(covered.begin() + static_cast<std::ptrdiff_t>(first), covered.begin() + static_cast<std::ptrdiff_t>(first) + pane.width, true);
    }
  }
  for (std::size_t i = 0; i < w * h; ++i) {
    if (!covered[i]) out[i] = metres(1.0);
  }
}

}  // namespace rbsim::render
