#pragma once
// Draws FrameData's particle sprites: one instanced draw call per batch, each particle a quad the
// vertex shader turns to face the camera (gl_VertexID picks the corner), sized in metres and
// coloured per particle, with a soft round falloff. Additive batches add light (fire), alpha
// batches cover what is behind them (smoke; the app sorts them back to front). Sprites are
// depth-tested against the opaque scene but write no depth, so they never hide each other.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "frame_data.h"
#include "gl_api.h"
#include "shader_program.h"

namespace rbsim::render {

class ParticleDraw {
 public:
  // Needs a current GL 4.5 compatibility context; throws RenderError if a shader is bad.
  explicit ParticleDraw(const std::string& shaderDir);
  ~ParticleDraw();
  ParticleDraw(const ParticleDraw&) = delete;
  ParticleDraw& operator=(const ParticleDraw&) = delete;

  // Uploads every batch's sprites into one instance buffer. Call once per frame, first.
  void upload(const FrameData& frame);
  // Alpha batches, then additive ones, over the opaque scene already in the framebuffer.
  void draw(const FrameData& frame, const glm::mat4& view, const glm::mat4& viewProj);

 private:
  struct Range {
    GLint first = 0;
    GLsizei count = 0;
    bool additive = false;
  };

  ShaderProgram program_;
  GLuint vao_ = 0, vbo_ = 0;
  std::vector<Sprite> staging_;  // reused every frame
  std::vector<Range> ranges_;
};

}  // namespace rbsim::render
