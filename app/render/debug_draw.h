#pragma once
// Draws FrameData's debug lines and points (AABBs, contact normals, contact points). Every frame
// they go to the GPU in one buffer upload and are drawn with at most three draw calls (depth-
// tested lines, on-top lines, points), however many there are: demo scenes have thousands.
//
// Each segment or point becomes a screen-space quad that the vertex shader builds (4 vertices
// that all carry the whole segment, plus a corner number; 6 indices from a fixed index pattern),
// with the antialiasing done per pixel in the fragment shader. That gives the same clean look
// with or without multisampling, any width, and discs clipped properly at the image border.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "frame_data.h"
#include "gl_api.h"
#include "shader_program.h"

namespace rbsim::render {

class DebugDraw {
 public:
  // Needs a current GL 4.5 compatibility context and the viewport size in pixels; throws
  // RenderError if a shader is bad.
  DebugDraw(int width, int height, const std::string& shaderDir);
  ~DebugDraw();
  DebugDraw(const DebugDraw&) = delete;
  DebugDraw& operator=(const DebugDraw&) = delete;

  // The viewport the next draws go to [px] (a comparison's pane, or the whole image).
  void setViewport(int width, int height) { viewport_ = glm::vec2(static_cast<float>(width), static_cast<float>(height)); }

  // Copies the frame's lines and points into the vertex buffer. Call once per frame, first.
  void upload(const FrameData& frame);

  // Lines without onTop, depth-tested (LEQUAL, no depth writes) against what is already drawn.
  void drawDepthTestedLines(const glm::mat4& viewProj, const glm::vec3& eye, float widthPx);
  // onTop lines, then every point, over everything drawn so far.
  void drawOnTop(const glm::mat4& viewProj, const glm::vec3& eye, float widthPx);

 private:
  // Attributes of debug_line.vert and debug_point.vert; a quad is 4 of these, corners 0..3.
  struct Vertex {
    glm::vec4 a;      // xyz: the segment's start, or the point; w: corner number
    glm::vec4 b;      // xyz: the segment's end; for a point, x is its diameter [px]
    glm::vec3 color;  // linear RGB
  };

  void appendQuad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& color);
  void ensureIndices(std::size_t quads);
  void drawLines(const glm::mat4& viewProj, const glm::vec3& eye, GLint first, GLsizei count,
                 float widthPx);

  glm::vec2 viewport_;
  ShaderProgram lineProgram_;
  ShaderProgram pointProgram_;
  GLuint vao_ = 0, vbo_ = 0, ibo_ = 0;
  std::size_t indexedQuads_ = 0;  // quads the index buffer covers; it only ever grows
  std::vector<Vertex> staging_;   // depth-tested lines, on-top lines, points; reused every frame
  GLsizei depthTestedCount_ = 0, onTopCount_ = 0, pointCount_ = 0;  // quads in each part
};

}  // namespace rbsim::render
