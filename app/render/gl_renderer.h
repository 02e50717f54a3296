#pragma once
// Draws one FrameData with OpenGL into the current context's default framebuffer: sky gradient,
// ground grid with planar shadows, flat-shaded bodies with outlines (optional wireframe), body
// axes and force arrows, see-through ghost bodies, particle sprites, debug lines and points. Bodies
// sharing a rigid mesh are drawn as instances (instanced_bodies.h). Multisampled into an
// off-screen framebuffer (when asked for), then resolved.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug_draw.h"
#include "depth_capture.h"
#include "frame_data.h"
#include "gl_api.h"
#include "instanced_bodies.h"
#include "pane_layout.h"
#include "pass_clock.h"
#include "projection.h"
#include "particle_draw.h"
#include "scene_geometry.h"
#include "shader_program.h"

namespace rbsim::render {

class GlRenderer {
 public:
  // Needs a current GL 4.5 compatibility context. samples > 1 renders with that many MSAA
  // samples (clamped to GL_MAX_SAMPLES); 1 draws straight into `target`, the context's
  // framebuffer object (gl_context.h).
  GlRenderer(int width, int height, const std::string& shaderDir, int samples, GLuint target);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // Sets every piece of GL state it relies on at the start, so whatever ran before (the ImGui
  // overlay of the previous frame) cannot leak in. Leaves the target bound with the image.
  // With `clock`, finishes after each pass and charges its time there (pass_clock.h). With
  // `depth`, copies the depth of the ground and the opaque bodies there (depth_capture.h).
  void draw(const FrameData& frame, PassClock* clock = nullptr, DepthCapture* depth = nullptr);

  int samples() const { return samples_; }

 private:
  // A framebuffer object of the image's size with samples_ samples: colour, depth and stencil.
  struct Target {
    GLuint fbo = 0, color = 0, depth = 0;
  };
  void createTarget(Target& target) const;
  static void deleteTarget(Target& target);
  // One scene (a whole frame, or a comparison's pane) into `pane` of frameTarget.
  void drawView(const FrameData& frame, const PaneRect& pane, GLuint frameTarget, PassClock* clock);
  // Sky and ground into `pane` of `into`, from background_ (redrawn there when the camera or the
  // pane's size changed).
  void drawBackground(const FrameData& frame, const glm::mat4& viewProj, GLuint into, const PaneRect& pane);
  void upload(const SceneGeometry& geometry);
  void drawSky(const FrameData& frame, const glm::mat4& viewProj);
  void drawGround(const FrameData& frame, const glm::mat4& viewProj);
  void drawShadows(const glm::mat4& viewProj);
  void setMeshUniforms(const ShaderProgram& program, const FrameData& frame,
                       const glm::mat4& viewProj, bool wireframe, float alpha) const;
  void drawMeshes(const FrameData& frame, const glm::mat4& viewProj, GLint first, GLsizei count,
                  bool wireframe, float alpha);
  void drawLines(const glm::mat4& viewProj, GLint first, GLsizei count, float widthPx,
                 float alpha);
  // Runs `draw` (line primitives, program bound) at widthPx, smoothed when not multisampled.
  void withLineState(float widthPx, const std::function<void()>& draw);
  void drawOpaqueBodies(const FrameData& frame, const glm::mat4& viewProj);
  void drawBodyEdges(const glm::mat4& viewProj);
  void drawOverlays(const FrameData& frame, const glm::mat4& viewProj);
  void drawGhosts(const FrameData& frame, const glm::mat4& viewProj);

  int width_;
  int height_;
  int samples_;
  float pixelScale_;  // line widths are given for a 720-pixel-high image and scaled by this
  ShaderProgram skyProgram_;
  ShaderProgram groundProgram_;
  ShaderProgram shadowProgram_;
  ShaderProgram meshProgram_;
  ShaderProgram lineProgram_;
  ShaderProgram meshInstancedProgram_;
  ShaderProgram shadowInstancedProgram_;
  ShaderProgram lineInstancedProgram_;
  InstancedBodies instanced_;
  DebugDraw debugDraw_;
  ParticleDraw particleDraw_;
  GLuint emptyVao_ = 0;  // for the buffer-less sky and ground draws
  GLuint meshVao_ = 0, meshVbo_ = 0;
  GLuint lineVao_ = 0, lineVbo_ = 0;
  GLuint target_ = 0;  // the context's framebuffer, which receives the image
  DepthCapture* depthCapture_ = nullptr;  // during a draw() asked for the depth image
  Target multisampled_;  // the frame is drawn here and resolved into target_ when samples_ > 1
  Target background_;    // sky and ground as seen from backgroundCamera_
  bool backgroundDrawn_ = false;
  bool backgroundGrid_ = false;
  Camera backgroundCamera_;
  int backgroundWidth_ = 0, backgroundHeight_ = 0;  // the pane size it was drawn for [px]
  // Reused every frame so steady-state frames allocate nothing.
  SceneGeometry geometry_;
  std::vector<MeshVertex> meshStaging_;  // bodies, ghosts, arrow heads, as uploaded
  std::vector<LineVertex> lineStaging_;  // edges, highlight, axes, shafts, ghost edges
  // Offsets (in vertices) of each group inside the two vertex buffers, set by upload().
  GLint ghostsFirst_ = 0, headsFirst_ = 0;
  GLint highlightFirst_ = 0, axesFirst_ = 0, shaftsFirst_ = 0, ghostEdgesFirst_ = 0;
};

}  // namespace rbsim::render
