#include "particle_draw.h"

#include <cstddef>

namespace rbsim::render {

ParticleDraw::ParticleDraw(const std::string& shaderDir) : program_(shaderDir, "sprite.vert", "sprite.frag") {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  const auto stride = static_cast<GLsizei>(sizeof(Sprite));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Sprite, position)));
  glVertexAttribDivisor(0, 1);  // per sprite, not per corner
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Sprite, size)));
  glVertexAttribDivisor(1, 1);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Sprite, color)));
  glVertexAttribDivisor(2, 1);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

ParticleDraw::~ParticleDraw() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void ParticleDraw::upload(const FrameData& frame) {
  staging_.clear();
  ranges_.clear();
  for (const SpriteBatch& batch : frame.sprites) {
    if (batch.sprites.empty()) continue;
    ranges_.push_back({static_cast<GLint>(staging_.size()), static_cast<GLsizei>(batch.sprites.size()), batch.additive});
    staging_.insert(staging_.end(), batch.sprites.begin(), batch.sprites.end());
  }
  if (staging_.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  // A fresh glBufferData each frame lets the driver orphan last frame's storage.
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(staging_.size() * sizeof(Sprite)), staging_.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ParticleDraw::draw(const FrameData& frame, const glm::mat4& view, const glm::mat4& viewProj) {
  if (ranges_.empty()) return;
  // The camera's right and up axes in world frame are the first two rows of the view rotation.
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
  const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
  program_.use();
  program_.set("uViewProj", viewProj);
  program_.set("uRight", right);
  program_.set("uUp", up);
  program_.set("uEye", frame.camera.eye);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBindVertexArray(vao_);
  for (bool additive : {false, true}) {
    // The image's alpha stays opaque (ZERO, ONE): PNG frames keep their alpha channel, and a
    // sprite must not make the picture see-through there.
    glBlendFuncSeparate(GL_SRC_ALPHA, additive ? GL_ONE : GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    for (const Range& range : ranges_) {
      if (range.additive != additive) continue;
      // The base instance starts the instance attributes at the batch (GL 4.2).
      glDrawArraysInstancedBaseInstance(GL_TRIANGLE_STRIP, 0, 4, range.count, static_cast<GLuint>(range.first));
    }
  }
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

}  // namespace rbsim::render
