#pragma once
// The segmentation image of a frame (issue 57): which surface each pixel shows, as an exact
// integer. A pass of its own into a 32-bit integer target: every opaque body's triangles written
// flat with the body's index in FrameData::bodies, the ground with kSegmentGround, nothing with
// kSegmentBackground; no lighting, blending, multisampling or outline, so a value is never a mix
// of two surfaces. The same triangles, projection and ground square as the colour pass, so its
// set of surfaces is the depth image's (depth_capture.h).
#include <cstdint>
#include <string>
#include <vector>

#include "frame_data.h"
#include "gl_api.h"
#include "pane_layout.h"
#include "shader_program.h"

namespace rbsim::render {

inline constexpr std::int32_t kSegmentBackground = -1;  // the sky: no surface
inline constexpr std::int32_t kSegmentGround = -2;      // the ground the renderer draws at y = 0 (options.grid)

class SegmentationPass {
 public:
  // Needs the current context. Throws RenderError naming a missing or broken shader.
  SegmentationPass(int width, int height, const std::string& shaderDir);
  ~SegmentationPass();
  SegmentationPass(const SegmentationPass&) = delete;
  SegmentationPass& operator=(const SegmentationPass&) = delete;

  // Draws the frame (each of a comparison's panes where the colour pass puts it). Sets every
  // piece of GL state it relies on; leaves its own framebuffer bound.
  void draw(const FrameData& frame);
  // The last draw, top row first.
  void read(std::vector<std::int32_t>& out);

 private:
  struct Vertex {
    glm::vec3 position;     // world frame [m]
    std::int32_t segment;   // the body's index in FrameData::bodies
  };
  void drawView(const FrameData& view, const PaneRect& pane);

  int width_, height_;
  ShaderProgram bodyProgram_;
  ShaderProgram groundProgram_;
  GLuint fbo_ = 0, ids_ = 0, depth_ = 0;
  GLuint vao_ = 0, vbo_ = 0, emptyVao_ = 0;
  std::vector<Vertex> vertices_;      // reused every frame
  std::vector<std::int32_t> rows_;    // bottom row first, as GL reads them
};

}  // namespace rbsim::render
