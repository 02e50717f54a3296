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
  // Needs the current context; the depth format of the frame's targets (DEPTH24_STENCIL8), which
  // glBlitFramebuffer requires of a depth copy.
  DepthCapture(int width, int height);
  ~DepthCapture();
  DepthCapture(const DepthCapture&) = delete;
  DepthCapture& operator=(const DepthCapture&) = delete;

  // Every pixel to the cleared depth 1 (no surface), so a comparison's gaps between panes read so.
  void clear();
  // Copies `pane` (pixels from the top left) of `source`'s depth to the same place. A
  // multisampled source gives one of each pixel's samples, never a mix of two surfaces.
  void capture(GLuint source, const PaneRect& pane, int imageHeight);
  // The captured depth, top row first, in metres along the camera axis; +inf where no surface.
  void readMetres(float nearPlane, float farPlane, std::vector<float>& out);

 private:
  int width_, height_;
  GLuint fbo_ = 0, depth_ = 0;
  std::vector<std::uint32_t> window_;  // depth-buffer values over 2^32 - 1, bottom row first as GL reads them
};

}  // namespace rbsim::render
