// GlRenderer's background: the sky gradient and the ground grid, drawn once per camera into a
// framebuffer of their own and copied into every frame (gl_renderer.h), and the framebuffer
// objects that hold them and the multisampled frame.
#include <algorithm>
#include <string>

#include "gl_renderer.h"
#include "render_error.h"

namespace rbsim::render {

namespace {

// Background palette in display (sRGB) values: the sky and ground shaders mix these directly,
// without lighting, so they need no per-pixel gamma encode (the costliest part on llvmpipe).
const glm::vec3 kZenith{0.13f, 0.17f, 0.24f};
const glm::vec3 kHorizon{0.56f, 0.61f, 0.67f};
const glm::vec3 kNadir{0.27f, 0.28f, 0.30f};
const glm::vec3 kGround{0.50f, 0.52f, 0.55f};
const glm::vec3 kGridMinor{0.46f, 0.48f, 0.51f};
const glm::vec3 kGridMajor{0.38f, 0.40f, 0.43f};

}  // namespace

void GlRenderer::createTarget(Target& target) const {
  // samples_ == 1: plain storage (0 samples), so blits to and from the context's framebuffer
  // are plain copies.
  const GLsizei samples = samples_ > 1 ? samples_ : 0;
  glGenRenderbuffers(1, &target.color);
  glBindRenderbuffer(GL_RENDERBUFFER, target.color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width_, height_);
  glGenRenderbuffers(1, &target.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, target.depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width_, height_);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &target.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, target.color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, target.depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, target_);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw RenderError("OpenGL: " + std::to_string(samples_) + "-sample framebuffer incomplete (status " +
                      std::to_string(status) + ")");
  }
}

void GlRenderer::deleteTarget(Target& target) {
  glDeleteFramebuffers(1, &target.fbo);
  glDeleteRenderbuffers(1, &target.color);
  glDeleteRenderbuffers(1, &target.depth);
  target = Target{};
}

void GlRenderer::drawBackground(const FrameData& frame, const glm::mat4& viewProj, GLuint into, const PaneRect& pane) {
  // Sky and ground depend only on the camera and the grid switch, and the scenes' cameras stand
  // still: their picture and depth are drawn once into background_ and copied into every frame
  // (a memory copy on llvmpipe, where shading them took 60 % of a one-body frame).
  const Camera& cam = frame.camera;
  const bool same = backgroundDrawn_ && backgroundGrid_ == frame.options.grid && cam.eye == backgroundCamera_.eye &&
                    cam.target == backgroundCamera_.target && cam.up == backgroundCamera_.up &&
                    cam.fovYDegrees == backgroundCamera_.fovYDegrees && cam.nearPlane == backgroundCamera_.nearPlane &&
                    cam.farPlane == backgroundCamera_.farPlane && pane.width == backgroundWidth_ &&
                    pane.height == backgroundHeight_;
  // Drawn at background_'s bottom left, whichever pane it is for: a comparison's panes share
  // one camera and one size, so it is drawn once for all of them.
  const GLint glY = height_ - pane.y - pane.height;
  if (!same) {
    glBindFramebuffer(GL_FRAMEBUFFER, background_.fbo);
    glViewport(0, 0, pane.width, pane.height);
    glScissor(0, 0, pane.width, pane.height);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);  // the sky covers every colour pixel
    if (frame.options.grid) drawGround(frame, viewProj);
    drawSky(frame, viewProj);
    backgroundDrawn_ = true;
    backgroundGrid_ = frame.options.grid;
    backgroundCamera_ = cam;
    backgroundWidth_ = pane.width;
    backgroundHeight_ = pane.height;
    glViewport(pane.x, glY, pane.width, pane.height);
    glScissor(pane.x, glY, pane.width, pane.height);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, background_.fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, into);
  glBlitFramebuffer(0, 0, pane.width, pane.height, pane.x, glY, pane.x + pane.width, glY + pane.height,
                    GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, into);
}

void GlRenderer::drawSky(const FrameData& frame, const glm::mat4& viewProj) {
  // Drawn after the ground, on the far plane: the depth test leaves only the pixels the ground
  // did not cover, so the gradient is not computed under it.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  skyProgram_.use();
  skyProgram_.set("uInvViewProj", glm::inverse(viewProj));
  skyProgram_.set("uEye", frame.camera.eye);
  skyProgram_.set("uZenith", kZenith);
  skyProgram_.set("uHorizon", kHorizon);
  // With the ground on, the plane fades into the horizon colour; keep that colour below the
  // horizon too so no seam shows where the ground square ends.
  skyProgram_.set("uNadir", frame.options.grid ? kHorizon : kNadir);
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GlRenderer::drawGround(const FrameData& frame, const glm::mat4& viewProj) {
  const Camera& cam = frame.camera;
  const float halfSize = kGroundHalfSizeOfFar * cam.farPlane;
  const float viewDistance = glm::length(cam.eye - cam.target);
  const float fadeEnd = 0.95f * halfSize;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  groundProgram_.use();
  groundProgram_.set("uViewProj", viewProj);
  groundProgram_.set("uCentre", glm::vec2(cam.eye.x, cam.eye.z));
  groundProgram_.set("uHalfSize", halfSize);
  groundProgram_.set("uEye", cam.eye);
  groundProgram_.set("uGroundColor", kGround);
  groundProgram_.set("uMinorColor", kGridMinor);
  groundProgram_.set("uMajorColor", kGridMajor);
  groundProgram_.set("uHorizon", kHorizon);
  groundProgram_.set("uMinorSpacing", 0.25f);
  groundProgram_.set("uMajorSpacing", 1.0f);
  groundProgram_.set("uLineWidth", std::max(1.0f, pixelScale_));
  groundProgram_.set("uFadeStart", std::min(3.0f * viewDistance, 0.5f * fadeEnd));
  groundProgram_.set("uFadeEnd", fadeEnd);
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

}  // namespace rbsim::render
