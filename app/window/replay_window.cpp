#include "window/replay_window.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

#include <imgui.h>

#include "rbsim/io/input_error.h"
#include "render/offscreen_renderer.h"
#include "render/pane_layout.h"
#include "render/png_sequence_writer.h"
#include "render/ui_frame.h"
#include "run/compare_view.h"
#include "run/frame_builder.h"
#include "window/replay_timeline.h"
#include "window/orbit_camera.h"
#include "window/x11_window.h"

namespace rbsim::app {

namespace {

using Clock = std::chrono::steady_clock;

constexpr float kTimelineHeightLines = 3.3f;  // the timeline bar's height [text lines]

class ReplayWindow {
 public:
  ReplayWindow(const std::vector<Phase>& phases, RecordReader& reader, const std::string& recording, const WindowOptions& options)
      : phases_(phases), timeline_(phases, reader, recording), title_(reader.header().title), options_(options) {
    if (title_.empty()) title_ = phases.front().scene().title;
  }

  void run() {
    const ViewDesc& view = phases_.front().scene().view;
    X11Window window(view.width, view.height, "rbsim replay: " + title_);
    render::OffscreenRenderer renderer(view.width, view.height, render::defaultShaderDir(),
                                       render::OffscreenRenderer::kDefaultSamples, options_.glBackend);
    WindowInput input;
    auto last = Clock::now();
    for (std::uint64_t shown = 0; options_.frames == 0 || shown < options_.frames; ++shown) {
      const auto frameStart = Clock::now();
      window.poll(input);
      if (input.closed || !handleKeys(input.keys)) break;
      handlePointer(input, renderer.uiWantsPointer());
      render::UiFrame ui;
      ui.input.mouseX = static_cast<float>(input.mouseX);
      ui.input.mouseY = static_cast<float>(input.mouseY);
      for (int b = 0; b < 3; ++b) ui.input.mouseDown[b] = input.down[b];
      ui.input.wheel = input.wheel;
      ui.input.deltaSeconds = std::max(render::kMinFrameSeconds, std::chrono::duration<float>(frameStart - last).count());
      last = frameStart;
      std::optional<std::size_t> wanted;
      ui.draw = [&] { wanted = drawTimeline(view.width, view.height); };
      const std::vector<std::uint8_t>& pixels = renderer.render(frame(), &ui);
      window.present(pixels);
      // The frame shown is the timeline's; then on to the one asked for, or the next.
      if (wanted) {
        timeline_.show(*wanted);
      } else if (playing_ && timeline_.current() + 1 < timeline_.frames()) {
        timeline_.show(timeline_.current() + 1);
      }
      if (options_.frames == 0) {
        const auto period = std::chrono::duration<double>(1.0 / view.fps);
        std::this_thread::sleep_until(frameStart + std::chrono::duration_cast<Clock::duration>(period));
      }
    }
    if (!options_.screenshot.empty()) {
      render::writePng(options_.screenshot, window.width(), window.height(), window.capture());
      if (!options_.quiet) std::printf("screenshot: %s\n", options_.screenshot.c_str());
    }
  }

 private:
  render::FrameData frame() const {
    const Phase& phase = timeline_.phase();
    render::FrameData f = buildPhaseFrame(timeline_.worlds(), phase, title_, &timeline_.freeFlight());
    f.overlay.plots = timeline_.plots();
    if (orbit_) {
      const ViewDesc& view = phase.scene().view;
      f.camera = orbit_->camera();
      const std::vector<render::PaneRect> rects = render::paneLayout(f.panes.size(), view.width, view.height, f.infoColumn, f.overlay.panel);
      for (std::size_t k = 0; k < f.panes.size(); ++k) {
        f.panes[k].camera = render::paneCamera(orbit_->camera(), view.width, view.height, rects[k]);
      }
    }
    f.overlay.plotsBottomInset = timelineHeight_;  // the plots stand on the timeline
    return f;
  }

  // false: quit.
  bool handleKeys(const std::string& keys) {
    for (char key : keys) {
      if (key == 'q' || key == '\x1b') return false;
      if (key == ' ') playing_ = !playing_;
      if (key == '.' && timeline_.current() + 1 < timeline_.frames()) pauseAt(timeline_.current() + 1);
      if (key == ',' && timeline_.current() > 0) pauseAt(timeline_.current() - 1);
      if (key == 'r') pauseAt(0);
    }
    return true;
  }

  void pauseAt(std::size_t frame) {
    playing_ = false;
    timeline_.show(frame);
  }

  void handlePointer(const WindowInput& input, bool overUi) {
    const int dx = input.mouseX - lastX_, dy = input.mouseY - lastY_;
    lastX_ = input.mouseX;
    lastY_ = input.mouseY;
    if (input.mouseX < 0 || overUi) return;
    const ViewDesc& view = timeline_.phase().scene().view;
    if (!orbit_ && (input.down[0] || input.down[1] || input.down[2] || input.wheel != 0.0f)) orbit_.emplace(sceneCamera(view));
    if ((input.down[0] || input.down[1]) && (dx != 0 || dy != 0) && !input.pressed[0] && !input.pressed[1]) orbit_->orbit(dx, dy);
    if (input.down[2] && (dx != 0 || dy != 0) && !input.pressed[2]) orbit_->pan(dx, dy, view.height);
    if (input.wheel != 0.0f) orbit_->zoom(input.wheel);
  }

  // The bar along the bottom: play or pause, a frame back or on, and a slider over every frame of
  // every phase. Returns the frame asked for, if any.
  std::optional<std::size_t> drawTimeline(int width, int height) {
    std::optional<std::size_t> wanted;
    const std::size_t current = timeline_.current(), frames = timeline_.frames();
    timelineHeight_ = kTimelineHeightLines * ImGui::GetTextLineHeightWithSpacing();
    ImGui::SetNextWindowPos(ImVec2(0.0f, static_cast<float>(height) - timelineHeight_));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(width), timelineHeight_));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("##rbsim-timeline", nullptr, flags)) {
      if (ImGui::Button(playing_ ? "Pause" : "Play ")) playing_ = !playing_;
      ImGui::SameLine();
      if (ImGui::Button("<") && current > 0) wanted = current - 1;
      ImGui::SameLine();
      if (ImGui::Button(">") && current + 1 < frames) wanted = current + 1;
      ImGui::SameLine();
      ImGui::Text("frame %zu of %zu   phase %zu of %zu   t = %.3f s      space: play/pause   , .: a frame back/on   r: start",
                  current + 1, frames, timeline_.phaseIndex() + 1, phases_.size(), timeline_.time());
      int index = static_cast<int>(current);
      ImGui::SetNextItemWidth(-1.0f);
      if (ImGui::SliderInt("##frame", &index, 0, static_cast<int>(frames) - 1, "")) wanted = static_cast<std::size_t>(index);
    }
    ImGui::End();
    if (wanted) playing_ = false;
    return wanted;
  }

  const std::vector<Phase>& phases_;
  ReplayTimeline timeline_;
  std::string title_;
  WindowOptions options_;
  bool playing_ = true;
  std::optional<OrbitCamera> orbit_;
  int lastX_ = -1, lastY_ = -1;
  float timelineHeight_ = 0.0f;
};

}  // namespace

void runReplayWindow(const std::vector<Phase>& phases, RecordReader& reader, const std::string& recording,
                     const WindowOptions& options) {
  ReplayWindow(phases, reader, recording, options).run();
}

}  // namespace rbsim::app
