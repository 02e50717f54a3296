#include "offscreen_renderer.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "data_dir.h"
#include "depth_capture.h"
#include "gl_renderer.h"
#include "overlay.h"
#include "render_error.h"
#include "segmentation_pass.h"

namespace rbsim::render {

namespace {
double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}
}  // namespace

struct OffscreenRenderer::Impl {
  // Declaration order is construction order: the context must exist before any GL object, and
  // is destroyed last.
  std::unique_ptr<GlContext> context;
  std::string shaderDir;
  GlRenderer scene;
  Overlay overlay;
  // Made at the first frame that asks for them, so a renderer that never does pays nothing.
  std::unique_ptr<DepthCapture> depthCapture;
  std::unique_ptr<SegmentationPass> segmentationPass;
  ExtraImages pendingExtra;             // what the pending frame asked for
  float pendingNear = 0.0f, pendingFar = 0.0f;  // its camera's planes [m], for the depth image
  std::vector<float> depth;             // the last frame's extra images
  std::vector<std::int32_t> segmentation;
  // Image buffers: `current` is the last image; the pool's others may still be with the writers.
  std::vector<std::shared_ptr<std::vector<std::uint8_t>>> pool;
  std::shared_ptr<std::vector<std::uint8_t>> current;
  MeanMs renderMs;
  MeanMs readbackMs;
  PassClock passes;
  long frames = 0;
  bool uiWantsPointer = false;
  bool pending = false;   // begin() ran, finish() not yet
  bool measured = false;  // the pending frame was timed pass by pass
  double issueMs = 0.0;   // begin()'s time for the pending frame

  Impl(int width, int height, const std::string& shaderDir, int samples, GlBackend backend)
      : context(makeGlContext(backend, width, height)),
        shaderDir(shaderDir),
        scene(width, height, shaderDir, samples, context->framebuffer()),
        overlay(width, height, context->framebuffer()) {}

  // A buffer of the pool that nobody else holds, or a new one.
  std::shared_ptr<std::vector<std::uint8_t>> freeBuffer() {
    current.reset();
    for (const auto& buffer : pool) {
      if (buffer.use_count() == 1) {
        // The last holder let go on another thread; see its writes before overwriting.
        std::atomic_thread_fence(std::memory_order_acquire);
        return buffer;
      }
    }
    const std::size_t bytes = static_cast<std::size_t>(context->width()) * static_cast<std::size_t>(context->height()) * 4;
    pool.push_back(std::make_shared<std::vector<std::uint8_t>>(bytes));
    return pool.back();
  }
};

OffscreenRenderer::OffscreenRenderer(int width, int height, std::string shaderDir, int samples,
                                     GlBackend backend)
    : impl_(std::make_unique<Impl>(width, height, shaderDir, samples, backend)) {}

OffscreenRenderer::~OffscreenRenderer() {
  // GL objects are deleted by the members' destructors; they need this context current.
  impl_->context->makeCurrent();
}

const std::vector<std::uint8_t>& OffscreenRenderer::render(const FrameData& frame, const UiFrame* ui, ExtraImages extra) {
  begin(frame, ui, extra);
  return finish();
}

void OffscreenRenderer::begin(const FrameData& frame, const UiFrame* ui, ExtraImages extra) {
  Impl& d = *impl_;
  if (d.pending) throw RenderError("OffscreenRenderer::begin: the previous frame was not finished");
  d.context->makeCurrent();
  if (extra.depth && !d.depthCapture) d.depthCapture = std::make_unique<DepthCapture>(width(), height(), samples());
  if (extra.segmentation && !d.segmentationPass) {
    d.segmentationPass = std::make_unique<SegmentationPass>(width(), height(), d.shaderDir);
  }
  d.pendingExtra = extra;
  // A comparison's panes share the scene camera's planes (paneCamera changes only the field of view).
  const Camera& camera = frame.panes.empty() ? frame.camera : frame.panes.front().camera;
  d.pendingNear = camera.nearPlane;
  d.pendingFar = camera.farPlane;
  // Frames measured pass by pass stay out of the mean: their extra flushes cost time.
  PassClock* clock = d.frames % kPassSampleEvery == kPassSampleEvery - 1 ? &d.passes : nullptr;
  const auto start = std::chrono::steady_clock::now();
  if (clock != nullptr) clock->begin();
  d.scene.draw(frame, clock, extra.depth ? d.depthCapture.get() : nullptr);
  // Off-screen, the overlay has no animation, so its time step only has to be positive.
  // Without the overlay (--no-overlay) the plots asked for still show: they are not the panel.
  // A comparison's captions stay too: without them the panes could not be told apart.
  OverlayData plotsOnly;
  if (!frame.options.overlay) {
    plotsOnly.plots = frame.overlay.plots;
    plotsOnly.panel = frame.overlay.panel;
    plotsOnly.plotsRight = frame.overlay.plotsRight;
    plotsOnly.plotsUnderPanel = frame.overlay.plotsUnderPanel;
    plotsOnly.plotsBottomInset = frame.overlay.plotsBottomInset;
    if (!frame.panes.empty()) plotsOnly.labels = frame.overlay.labels;
  }
  const float uiSeconds = ui != nullptr ? ui->input.deltaSeconds : 1.0f / 30.0f;
  d.uiWantsPointer = d.overlay.draw(frame.options.overlay ? frame.overlay : plotsOnly, uiSeconds, ui);
  // After the overlay, which leaves GL state of its own: the pass sets all it relies on, and the
  // next frame's colour pass does the same after it.
  if (extra.segmentation) d.segmentationPass->draw(frame);
  if (clock != nullptr) {
    clock->mark(RenderPass::Overlay, [] { glFinish(); });
    clock->endFrame();
  } else {
    glFlush();  // llvmpipe's threads rasterise from here on, while the caller does other work
  }
  d.pending = true;
  d.measured = clock != nullptr;
  d.issueMs = millisecondsSince(start);
}

const std::vector<std::uint8_t>& OffscreenRenderer::finish() {
  Impl& d = *impl_;
  if (!d.pending) throw RenderError("OffscreenRenderer::finish: no frame was begun");
  d.pending = false;
  d.context->makeCurrent();
  const auto start = std::chrono::steady_clock::now();
  glFinish();  // the framebuffer holds the image only once GL has finished
  // What rendering cost the caller: issuing the frame and waiting for the rest of it.
  if (!d.measured) d.renderMs.add(d.issueMs + millisecondsSince(start));
  // A GL error here is a bug in this library, not bad input; fail loudly rather than write a
  // subtly wrong video. (Mesa answers glGetError without a pipeline stall.)
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw RenderError(std::string("OpenGL error ") + code + " while rendering a frame");
  }

  const auto copyStart = std::chrono::steady_clock::now();
  d.current = d.freeBuffer();
  d.context->readTopDown(d.current->data());
  d.depth.clear();
  d.segmentation.clear();
  if (d.pendingExtra.depth) d.depthCapture->readMetres(d.pendingNear, d.pendingFar, d.depth);
  if (d.pendingExtra.segmentation) d.segmentationPass->read(d.segmentation);
  d.readbackMs.add(millisecondsSince(copyStart));
  ++d.frames;
  return *d.current;
}

std::shared_ptr<const std::vector<std::uint8_t>> OffscreenRenderer::finishShared() {
  finish();
  return impl_->current;
}

const std::vector<float>& OffscreenRenderer::depth() const { return impl_->depth; }
const std::vector<std::int32_t>& OffscreenRenderer::segmentation() const { return impl_->segmentation; }

bool OffscreenRenderer::uiWantsPointer() const { return impl_->uiWantsPointer; }

PanelLayout OffscreenRenderer::layoutPanel(const OverlayData& data) {
  impl_->context->makeCurrent();
  return impl_->overlay.layoutPanel(data);
}

int OffscreenRenderer::width() const { return impl_->context->width(); }
int OffscreenRenderer::height() const { return impl_->context->height(); }
int OffscreenRenderer::samples() const { return impl_->scene.samples(); }

RenderTiming OffscreenRenderer::timing() const {
  const Impl& d = *impl_;
  return {d.frames, d.renderMs.mean(), d.readbackMs.mean(), d.passes.frames(), d.passes.meanMs()};
}

}  // namespace rbsim::render
