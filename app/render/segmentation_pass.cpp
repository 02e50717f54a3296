#include "segmentation_pass.h"

#include <algorithm>
#include <cstddef>
#include <string>

#include "projection.h"
#include "render_error.h"
#include "scene_geometry.h"

namespace rbsim::render {

SegmentationPass::SegmentationPass(int width, int height, const std::string& shaderDir)
    : width_(width),
      height_(height),
      bodyProgram_(shaderDir, "segment.vert", "segment.frag"),
      groundProgram_(shaderDir, "ground.vert", "segment_ground.frag") {
  GLint previous = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glGenRenderbuffers(1, &ids_);
  glBindRenderbuffer(GL_RENDERBUFFER, ids_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_R32I, width, height);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ids_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &ids_);
    glDeleteRenderbuffers(1, &depth_);
    throw RenderError("OpenGL: the segmentation image's framebuffer is incomplete (status " + std::to_string(status) + ")");
  }
  glGenVertexArrays(1, &emptyVao_);
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribIPointer(1, 1, GL_INT, stride, reinterpret_cast<void*>(offsetof(Vertex, segment)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

SegmentationPass::~SegmentationPass() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteVertexArrays(1, &emptyVao_);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &ids_);
  glDeleteRenderbuffers(1, &depth_);
}

void SegmentationPass::draw(const FrameData& frame) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // meshes from files may have either winding, as in the colour pass
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  const GLint background = kSegmentBackground;
  glClearBufferiv(GL_COLOR, 0, &background);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  if (frame.panes.empty()) {
    drawView(frame, PaneRect{0, 0, width_, height_});
  } else {
    const std::vector<PaneRect> rects = paneLayout(frame.panes.size(), width_, height_, frame.infoColumn, frame.overlay.panel);
    for (std::size_t k = 0; k < frame.panes.size(); ++k) drawView(frame.panes[k], rects[k]);
  }
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, width_, height_);
  glBindVertexArray(0);
  glUseProgram(0);
}

void SegmentationPass::drawView(const FrameData& view, const PaneRect& pane) {
  const GLint glY = height_ - pane.y - pane.height;  // GL counts rows from the bottom
  glViewport(pane.x, glY, pane.width, pane.height);
  glScissor(pane.x, glY, pane.width, pane.height);
  glEnable(GL_SCISSOR_TEST);
  const glm::mat4 viewProj = viewProjection(view.camera, pane.width, pane.height);
  if (view.options.grid) {
    // ground.vert's square, as GlRenderer::drawGround places it.
    groundProgram_.use();
    groundProgram_.set("uViewProj", viewProj);
    groundProgram_.set("uCentre", glm::vec2(view.camera.eye.x, view.camera.eye.z));
    groundProgram_.set("uHalfSize", kGroundHalfSizeOfFar * view.camera.farPlane);
    groundProgram_.set("uSegment", static_cast<int>(kSegmentGround));
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  // Every opaque body from its world vertices, instanced or not in the colour pass: the engine's
  // own p' = R p + x, which the instanced path reproduces on the GPU.
  vertices_.clear();
  for (std::size_t b = 0; b < view.bodies.size(); ++b) {
    const BodyView& body = view.bodies[b];
    if (!(body.opacity >= 1.0f) || body.triangles == nullptr) continue;  // ghosts and hidden bodies are see-through
    const std::size_t count = body.worldVertices.size();
    const auto segment = static_cast<std::int32_t>(b);
    for (const auto& tri : *body.triangles) {
      if (tri[0] >= count || tri[1] >= count || tri[2] >= count) continue;  // as scene_geometry skips them
      for (const std::uint32_t corner : tri) vertices_.push_back({body.worldVertices[corner], segment});
    }
  }
  if (vertices_.empty()) return;
  bodyProgram_.use();
  bodyProgram_.set("uViewProj", viewProj);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(Vertex)), vertices_.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices_.size()));
}

void SegmentationPass::read(std::vector<std::int32_t>& out) {
  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);
  rows_.resize(w * h);
  out.resize(w * h);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_INT, rows_.data());
  for (std::size_t row = 0; row < h; ++row) {
    const std::int32_t* from = rows_.data() + (h - 1 - row) * w;
    std::copy(from, from + w, out.data() + row * w);
  }
}

}  // namespace rbsim::render
