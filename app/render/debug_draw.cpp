#include "debug_draw.h"

#include <cmath>
#include <cstdint>

namespace rbsim::render {

namespace {

// Fraction of the way to the eye that debug geometry is moved before projection. It does not
// change where a vertex lands on screen (it stays on the same view ray), only its depth: enough
// that a segment lying on a surface (an AABB's bottom on the ground, an AABB edge on a box edge)
// passes the depth test everywhere instead of stippling, small enough (1 cm at 10 m) that a
// segment really inside a body stays hidden.
constexpr float kDepthPull = 1e-3f;

constexpr GLsizei kIndicesPerQuad = 6;  // two triangles over 4 corners

bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

const void* indexOffset(GLsizei firstQuad) {
  return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(firstQuad) *
                                       kIndicesPerQuad * sizeof(GLuint));
}

}  // namespace

DebugDraw::DebugDraw(int width, int height, const std::string& shaderDir)
    : viewport_(static_cast<float>(width), static_cast<float>(height)),
      lineProgram_(shaderDir, "debug_line.vert", "debug_line.frag"),
      pointProgram_(shaderDir, "debug_point.vert", "debug_point.frag") {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glGenBuffers(1, &ibo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);  // part of the vertex array's state
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(Vertex, a)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(Vertex, b)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

DebugDraw::~DebugDraw() {
  glDeleteBuffers(1, &ibo_);
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void DebugDraw::appendQuad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& color) {
  for (int corner = 0; corner < 4; ++corner) {
    staging_.push_back({glm::vec4(a, static_cast<float>(corner)), glm::vec4(b, 0.0f), color});
  }
}

void DebugDraw::ensureIndices(std::size_t quads) {
  if (quads <= indexedQuads_) return;
  // Grown to twice the need, so a scene that slowly adds lines does not rebuild it every frame.
  indexedQuads_ = 2 * quads;
  std::vector<GLuint> indices;
  indices.reserve(indexedQuads_ * kIndicesPerQuad);
  for (std::size_t q = 0; q < indexedQuads_; ++q) {
    const auto base = static_cast<GLuint>(4 * q);
    for (const GLuint corner : {0u, 1u, 2u, 2u, 1u, 3u}) indices.push_back(base + corner);
  }
  glBindVertexArray(vao_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)),
               indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

void DebugDraw::upload(const FrameData& frame) {
  staging_.clear();
  // Non-finite input (a diverged body's AABB) is dropped here rather than handed to the
  // shaders, where it would make a quad of undefined shape.
  const auto addLines = [this, &frame](bool onTop) {
    const std::size_t before = staging_.size();
    for (const DebugLine& line : frame.lines) {
      if (line.onTop != onTop || !isFinite(line.a) || !isFinite(line.b)) continue;
      appendQuad(line.a, line.b, line.color);
    }
    return static_cast<GLsizei>((staging_.size() - before) / 4);
  };
  depthTestedCount_ = addLines(false);
  onTopCount_ = addLines(true);
  const std::size_t pointsFirst = staging_.size();
  for (const DebugPoint& point : frame.points) {
    if (!isFinite(point.position) || !(point.sizePixels > 0.0f)) continue;
    appendQuad(point.position, glm::vec3(point.sizePixels, 0.0f, 0.0f), point.color);
  }
  pointCount_ = static_cast<GLsizei>((staging_.size() - pointsFirst) / 4);
  if (staging_.empty()) return;
  ensureIndices(staging_.size() / 4);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  // A fresh glBufferData each frame lets the driver orphan last frame's storage.
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(staging_.size() * sizeof(Vertex)),
               staging_.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void DebugDraw::drawLines(const glm::mat4& viewProj, const glm::vec3& eye, GLint first,
                          GLsizei count, float widthPx) {
  if (count <= 0 || !(widthPx > 0.0f)) return;  // a zero, negative or NaN width draws nothing
  lineProgram_.use();
  lineProgram_.set("uViewProj", viewProj);
  lineProgram_.set("uEye", eye);
  lineProgram_.set("uPull", kDepthPull);
  lineProgram_.set("uViewport", viewport_);
  lineProgram_.set("uHalfWidth", 0.5f * widthPx);
  glEnable(GL_BLEND);  // the antialiased border
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, count * kIndicesPerQuad, GL_UNSIGNED_INT, indexOffset(first));
  glDisable(GL_BLEND);
}

void DebugDraw::drawDepthTestedLines(const glm::mat4& viewProj, const glm::vec3& eye,
                                     float widthPx) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);  // lines must not hide each other or the ghosts drawn after them
  drawLines(viewProj, eye, 0, depthTestedCount_, widthPx);
}

void DebugDraw::drawOnTop(const glm::mat4& viewProj, const glm::vec3& eye, float widthPx) {
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  drawLines(viewProj, eye, depthTestedCount_, onTopCount_, widthPx);
  if (pointCount_ <= 0) return;
  pointProgram_.use();
  pointProgram_.set("uViewProj", viewProj);
  pointProgram_.set("uViewport", viewport_);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, pointCount_ * kIndicesPerQuad, GL_UNSIGNED_INT,
                 indexOffset(depthTestedCount_ + onTopCount_));
  glDisable(GL_BLEND);
}

}  // namespace rbsim::render
