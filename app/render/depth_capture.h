#pragma once
// The depth image of a frame (issue 57): the colour pass's own depth buffer, copied out right
// after the ground and the opaque bodies are drawn, so it costs a memory copy and no second pass,
// and holds the surfaces only: the outlines, axes, arrows, particles and ghosts drawn later are
// annotations, and the segmentation image (segmentation_pass.h) does not have them either.
// Read back as metric depth along the camera axis (projection.h, linearDepth).
#include <cstdint>
#include <vector>

#include "gl_api.h"
#include "pane_layout.h"

namespace rbsim::render {

class DepthCapture {
 public:
  // Needs the current context. The depth format (DEPTH24_STENCIL8) and sample count of the frame's
  // targets, which glCopyImageSubData requires: a plain memory copy on llvmpipe, where a depth
  // glBlitFramebuffer is a draw writing gl_FragDepth (9 ms at 640 x 360 against 1 ms).
  DepthCapture(int width, int height, int samples);
  ~DepthCapture();
  DepthCapture(const DepthCapture&) = delete;
  DepthCapture& operator=(const DepthCapture&) = delete;

  // A new frame: no pane captured yet. Pixels no pane covers (a comparison's gaps) read +inf; they
  // are filled on the CPU, since a clear of this buffer would make llvmpipe wait for the frame.
  void startFrame() { panes_.clear(); }
  // Copies `pane` (pixels from the top left) of the depth attached to framebuffer `source` to the
  // same place.
  void capture(GLuint source, const PaneRect& pane, int imageHeight);
  // The captured depth, top row first, in metres along the camera axis; +inf where no surface.
  // Multisampled, each pixel is one of its samples (a blit resolves depth so), never a mix of two
  // surfaces.
  void readMetres(float nearPlane, float farPlane, std::vector<float>& out);

 private:
  // A framebuffer with one DEPTH24_STENCIL8 renderbuffer of `samples` samples (0: plain).
  static void makeTarget(int width, int height, int samples, GLuint& fbo, GLuint& depth);

  int width_, height_;
  GLuint fbo_ = 0, depth_ = 0;
  GLuint resolvedFbo_ = 0, resolvedDepth_ = 0;  // multisampled only: where readMetres resolves to
  std::vector<PaneRect> panes_;  // captured this frame
  std::vector<std::uint32_t> window_;  // depth << 8 | stencil, bottom row first as GL reads them
};

}  // namespace rbsim::render
