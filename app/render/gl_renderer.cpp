#include "gl_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/gtc/matrix_transform.hpp>

#include "render_error.h"

namespace rbsim::render {

namespace {

// Towards the light: high, from the left and a little in front of the default camera, so the
// top, +z and +x faces of a box get three clearly different shades, and shadows fall to the
// right where the camera sees them rather than hiding behind the bodies.
const glm::vec3 kLightDir = glm::normalize(glm::vec3(-0.35f, 1.0f, 0.45f));
constexpr float kShadowAlpha = 0.32f;
constexpr float kXrayAlpha = 0.3f;  // axes and arrows seen through a body
const glm::vec3 kPaneGapColor{0.08f, 0.09f, 0.11f};  // between a comparison's panes (sRGB)

// Line widths in pixels for a 720-pixel-high image; scaled with the image height.
constexpr float kEdgeWidth = 1.5f;
constexpr float kHighlightWidth = 3.0f;
constexpr float kAxisWidth = 3.0f;
constexpr float kShaftWidth = 3.5f;

void setMeshAttributes() {
  const auto stride = static_cast<GLsizei>(sizeof(MeshVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(MeshVertex, color)));
}

void setLineAttributes() {
  const auto stride = static_cast<GLsizei>(sizeof(LineVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(LineVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<void*>(offsetof(LineVertex, color)));
}

template <typename T>
void appendTo(std::vector<T>& all, const std::vector<T>& part) {
  all.insert(all.end(), part.begin(), part.end());
}

}  // namespace

GlRenderer::GlRenderer(int width, int height, const std::string& shaderDir, int samples, GLuint target)
    : width_(width),
      height_(height),
      samples_(1),
      // Small images get thinner lines, down to 0.6 of the 720p width.
      pixelScale_(std::max(0.6f, static_cast<float>(height) / 720.0f)),
      skyProgram_(shaderDir, "sky.vert", "sky.frag"),
      groundProgram_(shaderDir, "ground.vert", "ground.frag"),
      shadowProgram_(shaderDir, "shadow.vert", "shadow.frag"),
      meshProgram_(shaderDir, "mesh.vert", "mesh.frag", "lighting.glsl"),
      lineProgram_(shaderDir, "line.vert", "line.frag"),
      meshInstancedProgram_(shaderDir, "mesh_instanced.vert", "mesh.frag", "lighting.glsl"),
      shadowInstancedProgram_(shaderDir, "shadow_instanced.vert", "shadow.frag"),
      lineInstancedProgram_(shaderDir, "line_instanced.vert", "line.frag"),
      debugDraw_(width, height, shaderDir),
      particleDraw_(shaderDir),
      target_(target) {
  glGenVertexArrays(1, &emptyVao_);
  glGenVertexArrays(1, &meshVao_);
  glGenBuffers(1, &meshVbo_);
  glBindVertexArray(meshVao_);
  glBindBuffer(GL_ARRAY_BUFFER, meshVbo_);
  setMeshAttributes();
  glGenVertexArrays(1, &lineVao_);
  glGenBuffers(1, &lineVbo_);
  glBindVertexArray(lineVao_);
  glBindBuffer(GL_ARRAY_BUFFER, lineVbo_);
  setLineAttributes();
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);

  GLint maxSamples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  samples_ = std::clamp(samples, 1, std::max(1, static_cast<int>(maxSamples)));
  if (samples_ > 1) createTarget(multisampled_);
  createTarget(background_);
}

GlRenderer::~GlRenderer() {
  deleteTarget(multisampled_);
  deleteTarget(background_);
  glDeleteBuffers(1, &meshVbo_);
  glDeleteBuffers(1, &lineVbo_);
  glDeleteVertexArrays(1, &meshVao_);
  glDeleteVertexArrays(1, &lineVao_);
  glDeleteVertexArrays(1, &emptyVao_);
}

void GlRenderer::upload(const SceneGeometry& g) {
  // Opaque bodies first, then ghosts and arrow heads: the body range starts at vertex 0 and
  // every range is a multiple of 3, which mesh.vert's gl_VertexID % 3 (wireframe corners) and
  // the shadow pass (opaque bodies only: vertices [0, ghostsFirst_)) rely on.
  std::vector<MeshVertex>& meshes = meshStaging_;
  meshes.clear();
  appendTo(meshes, g.bodies);
  ghostsFirst_ = static_cast<GLint>(meshes.size());
  appendTo(meshes, g.ghosts);
  headsFirst_ = static_cast<GLint>(meshes.size());
  appendTo(meshes, g.arrowHeads);
  std::vector<LineVertex>& lines = lineStaging_;
  lines.clear();
  appendTo(lines, g.edges);
  highlightFirst_ = static_cast<GLint>(lines.size());
  appendTo(lines, g.highlight);
  axesFirst_ = static_cast<GLint>(lines.size());
  appendTo(lines, g.axes);
  shaftsFirst_ = static_cast<GLint>(lines.size());
  appendTo(lines, g.forceShafts);
  ghostEdgesFirst_ = static_cast<GLint>(lines.size());
  appendTo(lines, g.ghostEdges);
  // A fresh glBufferData each frame lets the driver orphan last frame's storage.
  glBindBuffer(GL_ARRAY_BUFFER, meshVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(meshes.size() * sizeof(MeshVertex)),
               meshes.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, lineVbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(LineVertex)),
               lines.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GlRenderer::drawShadows(const glm::mat4& viewProj) {
  // Blend once per pixel even where shadows of several triangles overlap: the stencil counts.
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_POLYGON_OFFSET_FILL);  // coplanar with the ground: pull towards the camera
  glPolygonOffset(-2.0f, -2.0f);
  for (const ShaderProgram* program : {&shadowProgram_, &shadowInstancedProgram_}) {
    program->use();
    program->set("uViewProj", viewProj);
    program->set("uLightDir", kLightDir);
    program->set("uAlpha", kShadowAlpha);
  }
  shadowProgram_.use();
  glBindVertexArray(meshVao_);
  glDrawArrays(GL_TRIANGLES, 0, ghostsFirst_);
  shadowInstancedProgram_.use();
  instanced_.drawShadows();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
}

void GlRenderer::setMeshUniforms(const ShaderProgram& program, const FrameData& frame,
                                 const glm::mat4& viewProj, bool wireframe, float alpha) const {
  program.use();
  program.set("uViewProj", viewProj);
  program.set("uEye", frame.camera.eye);
  program.set("uLightDir", kLightDir);
  program.set("uLightColor", glm::vec3(0.80f, 0.78f, 0.74f));
  program.set("uSkyAmbient", glm::vec3(0.34f, 0.36f, 0.40f));
  program.set("uGroundAmbient", glm::vec3(0.12f, 0.12f, 0.12f));
  program.set("uWireframe", wireframe ? 1 : 0);
  program.set("uWireColor", glm::vec3(0.02f, 0.02f, 0.03f));
  program.set("uAlpha", alpha);
}

void GlRenderer::drawMeshes(const FrameData& frame, const glm::mat4& viewProj, GLint first,
                            GLsizei count, bool wireframe, float alpha) {
  if (count <= 0) return;
  setMeshUniforms(meshProgram_, frame, viewProj, wireframe, alpha);
  glBindVertexArray(meshVao_);
  glDrawArrays(GL_TRIANGLES, first, count);
}

void GlRenderer::drawOpaqueBodies(const FrameData& frame, const glm::mat4& viewProj) {
  drawMeshes(frame, viewProj, 0, ghostsFirst_, frame.options.wireframe, 1.0f);
  if (instanced_.empty()) return;
  setMeshUniforms(meshInstancedProgram_, frame, viewProj, frame.options.wireframe, 1.0f);
  instanced_.drawSurfaces();
}

void GlRenderer::drawLines(const glm::mat4& viewProj, GLint first, GLsizei count, float widthPx,
                           float alpha) {
  if (count <= 0) return;
  lineProgram_.use();
  lineProgram_.set("uViewProj", viewProj);
  lineProgram_.set("uAlpha", alpha);
  glBindVertexArray(lineVao_);
  withLineState(widthPx, [first, count] { glDrawArrays(GL_LINES, first, count); });
}

void GlRenderer::drawBodyEdges(const glm::mat4& viewProj) {
  drawLines(viewProj, 0, static_cast<GLsizei>(geometry_.edges.size()), kEdgeWidth, 1.0f);
  if (instanced_.empty()) return;
  lineInstancedProgram_.use();
  lineInstancedProgram_.set("uViewProj", viewProj);
  lineInstancedProgram_.set("uAlpha", 1.0f);
  lineInstancedProgram_.set("uEdgeShade", kEdgeShade);
  withLineState(kEdgeWidth, [this] { instanced_.drawEdges(); });
}

void GlRenderer::withLineState(float widthPx, const std::function<void()>& draw) {
  glLineWidth(widthPx * pixelScale_);
  // Without multisampling, smooth lines are the antialiasing: they also cover the bodies'
  // silhouettes, since every silhouette edge of a box is a feature edge. Needs blending.
  const bool smooth = samples_ == 1;
  GLboolean blendWasOn = glIsEnabled(GL_BLEND);
  if (smooth) {
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  draw();
  if (smooth) {
    glDisable(GL_LINE_SMOOTH);
    if (!blendWasOn) glDisable(GL_BLEND);
  }
}

void GlRenderer::drawOverlays(const FrameData& frame, const glm::mat4& viewProj) {
  const auto axesCount = static_cast<GLsizei>(geometry_.axes.size());
  const auto shaftsCount = static_cast<GLsizei>(geometry_.forceShafts.size());
  const auto headsCount = static_cast<GLsizei>(geometry_.arrowHeads.size());
  // First the parts hidden inside or behind bodies, faint (depth GREATER), so a body's axes,
  // which start at its centre of mass, can be followed through it; then the visible parts.
  // The faint pass goes first so the arrows' own depth cannot hide it.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_GREATER);
  drawLines(viewProj, axesFirst_, axesCount, kAxisWidth, kXrayAlpha);
  drawLines(viewProj, shaftsFirst_, shaftsCount, kShaftWidth, kXrayAlpha);
  drawMeshes(frame, viewProj, headsFirst_, headsCount, false, kXrayAlpha);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LEQUAL);
  drawLines(viewProj, axesFirst_, axesCount, kAxisWidth, 1.0f);
  drawLines(viewProj, shaftsFirst_, shaftsCount, kShaftWidth, 1.0f);
  drawMeshes(frame, viewProj, headsFirst_, headsCount, false, 1.0f);
}

void GlRenderer::drawGhosts(const FrameData& frame, const glm::mat4& viewProj) {
  if (geometry_.ghostRanges.empty()) return;
  // Per ghost, farthest first: a depth-only pass, then colour where the depth matches, so only
  // the ghost's nearest surface blends in once. Drawn in one pass, its far side (culling is off)
  // would blend too and darken it unevenly. The depth it leaves behind only affects what comes
  // later: nearer ghosts (which pass) and its own outlines; everything on top ignores depth.
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);  // as for opaque bodies, so the outlines win at LEQUAL
  glPolygonOffset(1.0f, 1.0f);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (const GhostRange& ghost : geometry_.ghostRanges) {
    const GLint first = ghostsFirst_ + ghost.first;
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    drawMeshes(frame, viewProj, first, ghost.count, false, 1.0f);
    glEnable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    drawMeshes(frame, viewProj, first, ghost.count, frame.options.wireframe, ghost.opacity);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  // Outlines carry the ghost's opacity in their alpha: as faint as the ghost itself.
  drawLines(viewProj, ghostEdgesFirst_, static_cast<GLsizei>(geometry_.ghostEdges.size()),
            kEdgeWidth, 1.0f);
  glDisable(GL_BLEND);
}

void GlRenderer::draw(const FrameData& frame, PassClock* clock, DepthCapture* depth) {
  const GLuint frameTarget = samples_ > 1 ? multisampled_.fbo : target_;
  depthCapture_ = depth;
  if (depth != nullptr) depth->startFrame();
  if (frame.panes.empty()) {
    drawView(frame, PaneRect{0, 0, width_, height_}, frameTarget, clock);
  } else {
    // The gaps between the panes; each pane then covers its own rectangle.
    glBindFramebuffer(GL_FRAMEBUFFER, frameTarget);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(kPaneGapColor.r, kPaneGapColor.g, kPaneGapColor.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const std::vector<PaneRect> rects = paneLayout(frame.panes.size(), width_, height_, frame.infoColumn, frame.overlay.panel);
    for (std::size_t k = 0; k < frame.panes.size(); ++k) drawView(frame.panes[k], rects[k], frameTarget, clock);
  }
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, width_, height_);
  glBindVertexArray(0);
  glUseProgram(0);
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_.fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, target_);
  depthCapture_ = nullptr;
  if (clock != nullptr) clock->mark(RenderPass::Marks, [] { glFinish(); });
}

void GlRenderer::drawView(const FrameData& frame, const PaneRect& pane, GLuint frameTarget, PassClock* clock) {
  const auto mark = [clock](RenderPass pass) {
    if (clock != nullptr) clock->mark(pass, [] { glFinish(); });
  };
  buildSceneGeometry(frame, geometry_);
  upload(geometry_);
  instanced_.upload(frame);
  debugDraw_.upload(frame);
  particleDraw_.upload(frame);
  const glm::mat4 viewProj = viewProjection(frame.camera, pane.width, pane.height);
  mark(RenderPass::Upload);

  // GL counts rows from the bottom; the pane, from the top.
  const GLint glY = height_ - pane.y - pane.height;
  glBindFramebuffer(GL_FRAMEBUFFER, frameTarget);
  glViewport(pane.x, glY, pane.width, pane.height);
  glScissor(pane.x, glY, pane.width, pane.height);
  glEnable(GL_SCISSOR_TEST);
  debugDraw_.setViewport(pane.width, pane.height);
  glDisable(GL_CULL_FACE);  // meshes from files may have either winding
  glDisable(GL_BLEND);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  glClearDepth(1.0);
  glClearStencil(0);
  drawBackground(frame, viewProj, frameTarget, pane);
  mark(RenderPass::Background);

  // Bodies over the ground's depth, pushed slightly back so their outlines (drawn later at
  // LEQUAL) win the depth test; then the shadows on the ground wherever no body is in front.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  drawOpaqueBodies(frame, viewProj);
  glDisable(GL_POLYGON_OFFSET_FILL);
  // The depth image holds the surfaces: it is copied here, before axes, arrows or ghosts write
  // depth, or at the end when none will. Here the copy makes llvmpipe finish the frame so far
  // before it goes on, a wait that a busy machine stretches; at the end there is none.
  const bool annotationsWriteDepth = !geometry_.axes.empty() || !geometry_.forceShafts.empty() ||
                                     !geometry_.arrowHeads.empty() || !geometry_.ghostRanges.empty();
  if (depthCapture_ != nullptr && annotationsWriteDepth) depthCapture_->capture(frameTarget, pane, height_);
  mark(RenderPass::Bodies);
  if (frame.options.grid) {
    drawShadows(viewProj);
    mark(RenderPass::Shadows);
  }
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  drawBodyEdges(viewProj);
  drawLines(viewProj, highlightFirst_, static_cast<GLsizei>(geometry_.highlight.size()),
            kHighlightWidth, 1.0f);
  mark(RenderPass::Edges);
  particleDraw_.draw(frame, glm::lookAt(frame.camera.eye, frame.camera.target, frame.camera.up), viewProj);
  // Depth-tested debug lines before the ghosts, so they show through them; the on-top lines
  // and points last, over everything.
  const float debugWidth = frame.options.debugLineWidth * pixelScale_;
  debugDraw_.drawDepthTestedLines(viewProj, frame.camera.eye, debugWidth);
  glDepthMask(GL_TRUE);
  drawOverlays(frame, viewProj);
  drawGhosts(frame, viewProj);
  debugDraw_.drawOnTop(viewProj, frame.camera.eye, debugWidth);
  if (depthCapture_ != nullptr && !annotationsWriteDepth) depthCapture_->capture(frameTarget, pane, height_);
}

}  // namespace rbsim::render
