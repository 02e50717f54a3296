// rbsim.Renderer and rbsim.VideoWriter: the program's off-screen renderer (app/render) and its
// ffmpeg writer, so a notebook can show a frame of the current state or write a clip.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <memory>

#include "arguments.h"
#include "py_world.h"
#include "rbsim/io/input_error.h"
#include "rbsim/scene/scene_parts.h"
#include "render/offscreen_renderer.h"
#include "render/render_error.h"
#include "render/segmentation_pass.h"
#include "render/video_encoder.h"
#include "run/frame_builder.h"
#include "to_json.h"

namespace py = pybind11;

namespace rbsim::python {

namespace {

constexpr const char* kRendererCall = "Renderer()";
constexpr const char* kRenderCall = "Renderer.render()";
constexpr const char* kVideoCall = "VideoWriter()";
// The renderer's and H.264's limits, as the scene format's view.size has them.
constexpr int kMinPixels = 16;
constexpr int kMaxPixels = 8192;
// Frames waiting for ffmpeg: 8 frames of 1280 x 720 RGBA are 29 MB.
constexpr std::size_t kVideoQueueFrames = 8;

// Segmentation codes besides a body's row (render/segmentation_pass.h has the first two).
constexpr std::int32_t kSegmentOther = -3;  // a cloth, soft body or 2D body: drawn, but no row of the World
static_assert(render::kSegmentBackground == -1 && render::kSegmentGround == -2, "docs/python.md gives these codes");

// Removes `name` from the keywords and returns it: a bool, or `fallback` when not given.
bool takeBool(py::kwargs& keywords, const char* name, bool fallback) {
  if (!keywords.contains(name)) return fallback;
  const py::object value = keywords[name];
  PyDict_DelItemString(keywords.ptr(), name);
  if (!py::isinstance<py::bool_>(value)) {
    throw InputError(kRenderCall, name, std::string("expected a bool, got ") + Py_TYPE(value.ptr())->tp_name);
  }
  return value.cast<bool>();
}

void checkSize(const char* call, long long width, long long height) {
  for (const auto& [name, value] : {std::pair{"width", width}, std::pair{"height", height}}) {
    if (value < kMinPixels || value > kMaxPixels) {
      throw InputError(call, name, "expected a size in [" + std::to_string(kMinPixels) + ", " + std::to_string(kMaxPixels) +
                                       "] pixels, got " + std::to_string(value));
    }
    if (value % 2 != 0) throw InputError(call, name, "H.264 in yuv420p needs even width and height, got " + std::to_string(value));
  }
}

class PyRenderer {
 public:
  PyRenderer(long long width, long long height, long long samples, const std::string& gl) {
    checkSize(kRendererCall, width, height);
    if (samples < 1 || samples > 16) throw InputError(kRendererCall, "samples", "expected 1 to 16 samples per pixel");
    render::GlBackend backend = render::defaultGlBackend();
    if (!gl.empty()) {
      const std::optional<render::GlBackend> parsed = render::parseGlBackend(gl);
      if (!parsed) throw InputError(kRendererCall, "gl", "unknown backend \"" + gl + "\"; expected " + render::glBackendChoices());
      backend = *parsed;
    }
    renderer_ = std::make_unique<render::OffscreenRenderer>(static_cast<int>(width), static_cast<int>(height),
                                                            render::defaultShaderDir(), static_cast<int>(samples), backend);
  }

  // The world as the program draws it, under the world's view (a scene's "view" block, or the
  // default camera) with `view`'s keys over it: a new (height, width, 4) uint8 array, top row
  // first, alpha 255. With depth or segmentation, a dict of it and the images asked for.
  py::object render(const PyWorld& world, const py::object& selected, const py::kwargs& keywords) {
    py::kwargs view = keywords;
    const bool depth = takeBool(view, "depth", false);
    const bool segmentation = takeBool(view, "segmentation", false);
    const bool panel = takeBool(view, "panel", false);
    Scene scene = world.scene();
    parseViewBlock(toJson(view, kRenderCall, ""), kRenderCall, "", scene.view);
    if (panel) {
      if (view.contains("overlay") && !scene.view.overlay) {
        throw InputError(kRenderCall, "panel", "panel=True draws the panel, but overlay=False hides it; give one of them");
      }
      scene.view.overlay = true;
      if (scene.view.panel == ViewDesc::Panel::Off) scene.view.panel = ViewDesc::Panel::Compact;
    } else {
      scene.view.panel = ViewDesc::Panel::Off;
    }
    if (!selected.is_none()) scene.view.selected = world.index(bodyArgument(selected, kRenderCall, "selected"), kRenderCall);
    render::FrameData frame = app::buildFrame(world.world(), scene, "");
    app::placeBesidePanel(frame, scene.view);
    const std::vector<std::uint8_t>& rgba = renderer_->render(frame, nullptr, {depth, segmentation});
    const py::ssize_t h = renderer_->height(), w = renderer_->width();
    py::array_t<std::uint8_t> out({h, w, py::ssize_t{4}});
    std::uint8_t* pixels = out.mutable_data();
    std::memcpy(pixels, rgba.data(), rgba.size());
    // Opaque, as the PNG frames are (png_file.h): GL's alpha after blending is bookkeeping, and
    // antialiased outlines left at 0.8 would show as holes in imshow.
    for (std::size_t i = 3; i < rgba.size(); i += 4) pixels[i] = 255;
    if (!depth && !segmentation) return std::move(out);
    py::dict images;
    images["rgba"] = out;
    if (depth) {
      py::array_t<float> metres({h, w});
      std::memcpy(metres.mutable_data(), renderer_->depth().data(), renderer_->depth().size() * sizeof(float));
      images["depth"] = metres;
    }
    if (segmentation) {
      const auto& segments = renderer_->segmentation();
      py::array_t<std::int32_t> rows({h, w});
      std::int32_t* to = rows.mutable_data();
      // The frame's bodies are the World's rows, then the drawn surfaces that are no rigid body.
      const auto bodies = static_cast<std::int32_t>(world.world().bodies().size());
      for (std::size_t i = 0; i < segments.size(); ++i) to[i] = segments[i] >= bodies ? kSegmentOther : segments[i];
      images["segmentation"] = rows;
      py::list ids;
      for (std::int32_t row = 0; row < bodies; ++row) ids.append(world.wrap(world.world().idAt(static_cast<std::size_t>(row))));
      images["bodies"] = ids;
    }
    return std::move(images);
  }

  int width() const { return renderer_->width(); }
  int height() const { return renderer_->height(); }

 private:
  std::unique_ptr<render::OffscreenRenderer> renderer_;
};

class PyVideoWriter {
 public:
  PyVideoWriter(const std::string& path, long long width, long long height, long long fps) {
    checkSize(kVideoCall, width, height);
    if (fps < 1 || fps > 240) throw InputError(kVideoCall, "fps", "expected 1 to 240 frames per second");
    width_ = static_cast<int>(width);
    height_ = static_cast<int>(height);
    encoder_ = std::make_unique<render::VideoEncoder>(path, width_, height_, static_cast<int>(fps), kVideoQueueFrames);
  }

  // An (height, width, 4) uint8 array, as Renderer.render gives.
  void write(const py::handle& frameArg) {
    const auto frame = byteArrayArgument(frameArg, "VideoWriter.write()", "frame");
    if (!encoder_) throw render::RenderError("VideoWriter.write(): the video is closed");
    if (frame.ndim() != 3 || frame.shape(0) != height_ || frame.shape(1) != width_ || frame.shape(2) != 4) {
      throw InputError("VideoWriter.write()", "frame",
                       "expected a (" + std::to_string(height_) + ", " + std::to_string(width_) + ", 4) uint8 array");
    }
    auto pixels = std::make_shared<std::vector<std::uint8_t>>(frame.data(), frame.data() + frame.size());
    encoder_->submit({frames_++, std::move(pixels)});
    if (const std::string error = encoder_->error(); !error.empty()) throw render::RenderError(error);
  }

  // A writer dropped without close() finishes its video, as Python's files flush when collected.
  ~PyVideoWriter() {
    try {
      close();
    } catch (...) {
      // Destructors must not throw; close() reports the error to callers who want it.
    }
  }
  PyVideoWriter(PyVideoWriter&&) = default;

  // Waits for ffmpeg to finish the file; RenderError with its output when it failed.
  void close() {
    if (!encoder_) return;
    std::unique_ptr<render::VideoEncoder> encoder = std::move(encoder_);
    encoder->finish();
  }

  // The with-block ended by an exception: the video is thrown away, not left half made.
  void abandon() {
    if (encoder_) encoder_->abandon();
    encoder_.reset();
  }

  long frames() const { return frames_; }

 private:
  int width_ = 0;
  int height_ = 0;
  long frames_ = 0;
  std::unique_ptr<render::VideoEncoder> encoder_;
};

}  // namespace

void bindRendering(py::module_& m) {
  py::class_<PyRenderer>(m, "Renderer", "The off-screen OpenGL renderer of `rbsim run` (OSMesa or EGL, llvmpipe).")
      .def(py::init([](const py::object& width, const py::object& height, const py::object& samples, const py::object& gl) {
             return std::make_unique<PyRenderer>(intArgument(width, kRendererCall, "width"),
                                                 intArgument(height, kRendererCall, "height"),
                                                 intArgument(samples, kRendererCall, "samples"),
                                                 stringArgument(gl, kRendererCall, "gl"));
           }),
           py::arg("width") = 640, py::arg("height") = 360, py::arg("samples") = 1, py::arg("gl") = "",
           "__init__(self, /, width=640, height=360, samples=1, gl='')\n--\n\ngl \"\" picks the program's default "
           "backend")
      .def("render",
           [](PyRenderer& r, const py::object& world, const py::object& selected, const py::kwargs& view) {
             return r.render(worldArgument(world, kRenderCall), selected, givenKeywords(view));
           },
           py::arg("world"), py::arg("selected") = py::none(),
           "render(self, /, world, selected=None, *, depth=False, segmentation=False, panel=False, camera=None, "
           "overlay=None, wireframe=None, axes=None, grid=None, caption=None)\n--\n\n-> (height, width, 4) uint8 RGBA; "
           "with depth or segmentation a dict: rgba, depth (height, width) float32 metres along the camera axis (inf: "
           "sky), segmentation (height, width) int32 body row (-1 sky, -2 ground, -3 another surface), bodies (the "
           "BodyId of each row). panel: draw the variables panel. The other keywords are those of a scene's \"view\" "
           "block (camera={eye, target, up, fov_deg}); None: the view's default. selected: the BodyId the panel shows")
      .def_property_readonly("width", &PyRenderer::width)
      .def_property_readonly("height", &PyRenderer::height);

  py::class_<PyVideoWriter>(m, "VideoWriter", "An H.264 MP4 written by ffmpeg, as `rbsim run --video` writes.")
      .def(py::init([](const py::object& path, const py::object& width, const py::object& height, const py::object& fps) {
             return std::make_unique<PyVideoWriter>(pathArgument(path, kVideoCall, "path"), intArgument(width, kVideoCall, "width"),
                                                    intArgument(height, kVideoCall, "height"), intArgument(fps, kVideoCall, "fps"));
           }),
           py::arg("path"), py::arg("width"), py::arg("height"), py::arg("fps") = 30,
           "__init__(self, /, path, width, height, fps=30)\n--\n\nan H.264 MP4 at fps frames per second")
      .def("write", &PyVideoWriter::write, py::arg("frame"), "write(self, /, frame)\n--\n\nframe: a (height, width, 4) uint8 array, as Renderer.render gives")
      .def("close", &PyVideoWriter::close, "close(self, /)\n--\n\nwaits for ffmpeg to finish the file")
      .def_property_readonly("frames", &PyVideoWriter::frames)
      .def("__enter__", [](PyVideoWriter& w) -> PyVideoWriter& { return w; })
      .def("__exit__", [](PyVideoWriter& w, const py::args& exc) {
        if (!exc.empty() && !exc[0].is_none()) {
          w.abandon();
        } else {
          w.close();
        }
      });
}

}  // namespace rbsim::python
