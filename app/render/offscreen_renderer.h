#pragma once
// The renderer's public face: FrameData in, a top-down RGBA8 image out. Owns the GL context,
// the GL scene renderer and the ImGui overlay. Not thread-safe: create it and call render() on
// one thread (the GL context is current there); hand images to a FrameSink for output.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "data_dir.h"  // defaultShaderDir
#include "frame_data.h"
#include "gl_context.h"
#include "panel_layout.h"
#include "timing.h"
#include "ui_frame.h"

namespace rbsim::render {

// The images a frame makes besides the colour one (issue 57), each only when asked for: the
// default frame costs what it did.
struct ExtraImages {
  // Metres along the camera axis of the ground and the opaque bodies, read from the colour pass's
  // own depth buffer (depth_capture.h); +inf where the sky is.
  bool depth = false;
  // Per pixel the index in FrameData::bodies of the opaque body seen, kSegmentGround or
  // kSegmentBackground (segmentation_pass.h): a flat integer pass of its own.
  bool segmentation = false;
};

class OffscreenRenderer {
 public:
  // No multisampling by default: on llvmpipe 4x MSAA shades every sample and took 1280x720 from
  // ~16 to ~47 ms per frame. Edges are antialiased anyway: the grid in its shader, and bodies by
  // their smooth outline lines. Pass 4 for the last bit of quality (e.g. a final video).
  static constexpr int kDefaultSamples = 1;

  // Throws RenderError if no GL context can be made or a shader is missing or does not compile
  // (the message names the file).
  OffscreenRenderer(int width, int height, std::string shaderDir = defaultShaderDir(),
                    int samples = kDefaultSamples, GlBackend backend = defaultGlBackend());
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  // Renders one frame (overlay included when frame.options.overlay; with `ui`, its control
  // windows too) and returns the image: width*height*4 bytes, RGBA, top row first. Valid until
  // the next render() call.
  const std::vector<std::uint8_t>& render(const FrameData& frame, const UiFrame* ui = nullptr, ExtraImages extra = {});
  // render() in two halves, so the caller can work while llvmpipe's threads rasterise: begin()
  // issues the frame's GL commands and flushes them (nothing refers to `frame` afterwards);
  // finish() waits for the picture and returns it like render(). Each begin() needs its
  // finish() before the next begin(); RenderError otherwise.
  void begin(const FrameData& frame, const UiFrame* ui = nullptr, ExtraImages extra = {});
  const std::vector<std::uint8_t>& finish();
  // finish(), the image shared instead of borrowed: the writers keep it as long as they need it
  // and it is never copied; its buffer is reused once nobody holds it any more.
  std::shared_ptr<const std::vector<std::uint8_t>> finishShared();
  // The extra images of the last finish(), width*height values, top row first; empty when that
  // frame did not ask for them. Valid until the next finish().
  const std::vector<float>& depth() const;
  const std::vector<std::int32_t>& segmentation() const;
  // Whether ImGui wanted the pointer during the last render() with a UiFrame (it was over a
  // control), so the window does not also turn the drag into a camera move or a pick.
  bool uiWantsPointer() const;

  // Where the overlay panel of `data` goes and each line of its text, as render() lays it out
  // (panel_layout.h; tests check that no text leaves its box).
  PanelLayout layoutPanel(const OverlayData& data);

  int width() const;
  int height() const;
  int samples() const;  // after clamping to what the driver offers
  RenderTiming timing() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rbsim::render
