#include "window/interactive.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>
#include <utility>

#include "rbsim/io/input_error.h"
#include "render/debug_shapes.h"
#include "render/frame_sink.h"
#include "render/offscreen_renderer.h"
#include "render/ui_frame.h"
#include "render/png_sequence_writer.h"
#include "render/render_error.h"
#include "run/frame_builder.h"
#include "run/phase.h"
#include "run/plot_history.h"
#include "run/runner.h"
#include "run/to_glm.h"
#include "rbsim/scene/scene.h"
#include "window/control_panel.h"
#include "window/orbit_camera.h"
#include "window/picking.h"
#include "window/x11_window.h"
#include "rbsim/integrate/simulation_error.h"

namespace rbsim::app {

namespace {

using Clock = std::chrono::steady_clock;

// Arrows of the drag: the force is drawn 1 m long per body weight m|g| (or per m * 9.81 N when
// there is no gravity), the torque about the centre of mass 1 m per weight times metre.
constexpr double kStandardGravity = 9.81;     // [m/s^2]
// The shown rate is averaged over about this many frames' worth: 1 / kRateSmoothing [1].
constexpr double kRateSmoothing = 0.1;

constexpr glm::vec3 kDragForceColor{1.0f, 1.0f, 1.0f};
constexpr glm::vec3 kDragTorqueColor{0.3f, 1.0f, 0.4f};

// `s` as one single-quoted word for a POSIX shell; a quote inside closes, escapes and reopens.
std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

class Session {
 public:
  Session(const SceneSource& source, const WindowOptions& options)
      : source_(source), options_(options), speed_(options.speed) {
    scene_ = load(phase_, {});
    world_ = std::make_unique<World>(buildFramedWorld(scene_));
    watchFreeFlight();
  }

  void run() {
    // A screenshot that cannot be written fails now, not after the whole scripted session.
    const std::filesystem::path shot(options_.screenshot);
    if (shot.has_parent_path()) render::ensureWritableDirectory(shot.parent_path());
    if (!shot.empty() && std::filesystem::is_directory(shot)) {
      throw render::RenderError("cannot write the screenshot " + shot.string() + ": it is a folder");
    }
    X11Window window(scene_.view.width, scene_.view.height, "rbsim: " + title());
    window_ = &window;
    render::OffscreenRenderer renderer(scene_.view.width, scene_.view.height, render::defaultShaderDir(),
                                       render::OffscreenRenderer::kDefaultSamples, options_.glBackend);
    WindowInput input;
    auto last = Clock::now();
    for (std::uint64_t shown = 0; options_.frames == 0 || shown < options_.frames; ++shown) {
      const auto frameStart = Clock::now();
      window.poll(input);
      if (input.closed || !handleKeys(input.keys)) break;
      handlePointer(input, renderer.uiWantsPointer());
      if (!paused_) advanceOneFrame();

      render::UiFrame ui;
      ui.input.mouseX = static_cast<float>(input.mouseX);
      ui.input.mouseY = static_cast<float>(input.mouseY);
      for (int b = 0; b < 3; ++b) ui.input.mouseDown[b] = input.down[b];
      ui.input.wheel = input.wheel;
      ui.input.deltaSeconds = std::max(render::kMinFrameSeconds, std::chrono::duration<float>(frameStart - last).count());
      last = frameStart;
      PanelRequests requests;
      ui.draw = [&] { requests = drawControlPanel(panelView(), scene_.view.width, scene_.view.height); };
      const std::vector<std::uint8_t>& pixels = renderer.render(frame(), &ui);
      window.present(pixels);
      if (recorder_) recorder_->submit(pixels);
      apply(requests);
      // Real time (times the speed) in scripted runs too: frame k waits for its time, 1/fps
      // after the previous one; a frame that takes longer only slows the playback.
      const auto period = std::chrono::duration<double>(1.0 / scene_.view.fps);
      std::this_thread::sleep_until(frameStart + std::chrono::duration_cast<Clock::duration>(period));
      const double realSeconds = std::chrono::duration<double>(Clock::now() - frameStart).count();
      const double rate = paused_ ? speed_ : speed_ * period.count() / std::max(realSeconds, period.count());
      shownRate_ += kRateSmoothing * (rate - shownRate_);
    }
    window_ = nullptr;
    if (recorder_) stopRecording();
    if (!options_.screenshot.empty()) {
      render::writePng(options_.screenshot, window.width(), window.height(), window.capture());
      if (!options_.quiet) std::printf("screenshot: %s\n", options_.screenshot.c_str());
    }
  }

 private:
  std::string title() const { return source_.title.empty() ? scene_.title : source_.title; }

  std::vector<std::string> overrides(const std::vector<std::pair<std::string, std::string>>& panel) const {
    std::vector<std::string> all = source_.overrides;
    for (const auto& [path, value] : panel) all.push_back(path + "=" + value);
    return all;
  }

  // A compared phase (run/phase.h) shows its first world only: picking, dragging and the panel's
  // physics act on one World. The caption says so; the video (`rbsim run`) shows them all.
  Scene load(std::size_t phase, const std::vector<std::pair<std::string, std::string>>& panel) const {
    Phase loaded = loadPhase(source_.files[phase], overrides(panel));
    Scene scene = std::move(loaded.worlds.front().scene);
    if (loaded.compared()) {
      scene.view.caption = "window mode shows the first of the " + std::to_string(loaded.worlds.size()) +
                           " compared worlds (" + loaded.compareKey + "): " + loaded.worlds.front().label +
                           "; the video shows them side by side. " + scene.view.caption;
    }
    return scene;
  }

  // Frame k shows the step nearest k / fps, as in the off-screen runner, so that the window and
  // the video agree frame for frame.
  // At a speed other than 1 the playhead moves by `speed` frames a frame: in slow motion the
  // steps between two video frames are shown one by one, fast forward skips frames.
  void advanceOneFrame() {
    const double step = std::round(playhead_ / (scene_.view.fps * scene_.settings.timeStep));
    stepUntil(step >= static_cast<double>(kHugeCount) ? kHugeCount : static_cast<std::uint64_t>(step));
    playhead_ += speed_;
  }

  void stepUntil(std::uint64_t target) {
    try {
      while (world_->stepCount() < target) {
        world_->step();
        freeFlight_->observe(*world_);
      }
      plots_->sample(*world_, &*freeFlight_);
    } catch (const SimulationError& e) {
      paused_ = true;
      message_ = std::string("diverged, paused: ") + e.what();
    }
    history_.add(world_->bodies()[scene_.view.selected]);
  }

  void stepOnce() {
    stepUntil(world_->stepCount() + 1);
    // The next frame is the first one at or after this step.
    playhead_ = std::max(playhead_, static_cast<double>(firstFrameShowing(world_->stepCount(), scene_.view.fps,
                                                                         scene_.settings.timeStep)));
  }

  void restart() {
    drag_.reset();
    world_ = std::make_unique<World>(buildFramedWorld(scene_));
    watchFreeFlight();
    playhead_ = 0.0;
    history_.clear();
  }

  // false: quit.
  bool handleKeys(const std::string& keys) {
    for (char key : keys) {
      if (key == 'q' || key == '\x1b') return false;
      if (key == ' ') paused_ = !paused_;
      if (key == 's') stepOnce();
      if (key == 'r') restart();
      if (key == 'c') copyCommandLine();
    }
    return true;
  }

  render::Camera camera() const { return orbit_ ? orbit_->camera() : viewCamera(*world_, scene_.view); }

  // The ray through window pixel (x, y). The window draws the scene over the whole image, its
  // panels over it: the user moves the camera where they cover a body.
  Ray sceneRay(double x, double y) const { return pixelRay(camera(), scene_.view.width, scene_.view.height, x, y); }

  OrbitCamera& orbit() {
    if (!orbit_) orbit_.emplace(camera());
    return *orbit_;
  }

  void handlePointer(const WindowInput& input, bool overPanel) {
    const int dx = input.mouseX - lastX_, dy = input.mouseY - lastY_;
    lastX_ = input.mouseX;
    lastY_ = input.mouseY;
    dropStaleDrag();
    if (input.pressed[0] && !overPanel && input.mouseX >= 0) grab(input.mouseX, input.mouseY);
    if (!input.down[0]) {
      if (drag_) removeSpring(*world_, drag_->spring);
      drag_.reset();
      orbitingWithLeft_ = false;
    }
    if (drag_) {
      const Ray ray = sceneRay(input.mouseX, input.mouseY);
      if (const auto anchor = rayPlane(ray, drag_->planePoint, drag_->planeNormal)) moveSpringAnchor(*world_, drag_->spring, *anchor);
    }
    if (input.mouseX < 0 || (overPanel && !orbitingWithLeft_ && !input.down[1] && !input.down[2])) return;
    if ((orbitingWithLeft_ || input.down[1]) && (dx != 0 || dy != 0) && !input.pressed[0] && !input.pressed[1]) orbit().orbit(dx, dy);
    if (input.down[2] && (dx != 0 || dy != 0) && !input.pressed[2]) orbit().pan(dx, dy, scene_.view.height);
    if (input.wheel != 0.0f && !overPanel) orbit().zoom(input.wheel);
  }

  // The dragged body left the World (a kill volume, a spawner's lifetime) and took the drag's
  // spring with it: the drag ends.
  void dropStaleDrag() {
    if (drag_ && !isValid(*world_, drag_->spring)) drag_.reset();
  }

  // A left press on a body selects it and, unless it is static, starts dragging it; on empty
  // space it starts orbiting.
  void grab(int x, int y) {
    const Ray ray = sceneRay(x, y);
    const std::optional<Pick> pick = pickBody(*world_, ray);
    if (!pick) {
      orbitingWithLeft_ = true;
      return;
    }
    scene_.view.selected = pick->body;
    setPanelValue("view.selected", "\"" + scene_.bodies[pick->body].name + "\"");
    history_.clear();
    const RigidBody& body = world_->bodies()[pick->body];
    if (body.isStatic()) return;
    const Spring spring = dragSpring(world_->idAt(pick->body), body, pick->point);  // world/spring.h
    drag_ = Drag{addSpring(*world_, spring), pick->point, -ray.direction};
    moveSpringAnchor(*world_, drag_->spring, pick->point);  // wakes the body
  }

  render::FrameData frame() {
    render::FrameData f = buildFrame(*world_, scene_, title(), true, &*freeFlight_);
    if (!plots_->empty()) {
      f.overlay.plots = plots_->plots();
      // Left of the control panel, which holds the right-hand side of the window.
      f.overlay.plotsRight = panelRect(scene_.view.width, scene_.view.height).x - 8.0f;
    }
    if (orbit_) f.camera = orbit_->camera();
    dropStaleDrag();
    if (drag_) {
      const Spring& spring = springs(*world_)[indexOf(*world_, drag_->spring)];
      const RigidBody& body = world_->body(spring.body);
      const auto [point, force] = forceOfSpring(spring, body);
      const double gravity = world_->settings().gravity.norm() > 0.0 ? world_->settings().gravity.norm() : kStandardGravity;
      const double weight = body.mass() * gravity;  // [N]
      const Vec3 torque = (point - body.position()).cross(force);
      const Vec3 anchor = spring.anchor;
      f.lines.push_back({toGlm(point), toGlm(anchor), kDragForceColor, true});
      render::appendArrowLines(f.lines, toGlm(point), toGlm(Vec3(point + force / weight)), kDragForceColor);
      render::appendArrowLines(f.lines, toGlm(body.position()), toGlm(Vec3(body.position() + torque / weight)),
                               kDragTorqueColor);
      f.overlay.rows.push_back({"drag force", format3(force, "N"), render::RowLevel::Action});
      f.overlay.rows.push_back({"drag torque", format3(torque, "N m"), render::RowLevel::Action});
    }
    return f;
  }

  static std::string format3(const Vec3& v, const char* unit) {
    char text[96];
    std::snprintf(text, sizeof text, "%+.3f %+.3f %+.3f %s", v.x(), v.y(), v.z(), unit);
    return text;
  }

  PanelView panelView() {
    PanelView v;
    v.scene = &scene_;
    v.world = world_.get();
    v.history = &history_;
    v.phases = source_.files;
    v.phase = phase_;
    v.paused = paused_;
    v.recording = recorder_ != nullptr;
    v.recordingPath = recordingPath_;
    v.message = message_;
    v.scenes = scenes_;
    v.speed = speed_;
    v.shownRate = shownRate_;
    return v;
  }

  void setPanelValue(const std::string& path, const std::string& value) {
    for (auto& entry : panel_) {
      if (entry.first == path) {
        entry.second = value;
        return;
      }
    }
    panel_.emplace_back(path, value);
  }

  void apply(const PanelRequests& r) {
    if (r.togglePause) paused_ = !paused_;
    if (r.step) stepOnce();
    if (r.reset) restart();
    if (r.phase >= 0 && static_cast<std::size_t>(r.phase) != phase_) switchPhase(static_cast<std::size_t>(r.phase));
    if (!r.scene.empty() && r.scene != source_.files[phase_]) switchScene(r.scene);
    if (r.speed > 0.0) speed_ = std::clamp(r.speed, kMinPlaybackSpeed, kMaxPlaybackSpeed);
    for (const PanelRequests::Assignment& a : r.assignments) assign(a);
    if (r.toggleRecording) recorder_ ? stopRecording() : startRecording();
    if (r.copyCommand) copyCommandLine();
  }

  // The command that reruns what the window shows: on the clipboard (paste it into a terminal)
  // and printed.
  void copyCommandLine() {
    const std::string line = commandLine();
    if (window_ != nullptr) window_->setClipboard(line);
    message_ = "copied: " + line;
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }

  // The scene picker: another scene file, from t = 0 with its own settings.
  void switchScene(const std::string& file) {
    const SceneSource before = source_;
    try {
      source_.files = {file};
      source_.title.clear();
      scene_ = load(0, {});
    } catch (const InputError& e) {
      source_ = before;
      message_ = e.what();
      return;
    }
    phase_ = 0;
    panel_.clear();
    message_.clear();
    drag_.reset();
    orbit_.reset();
    restart();
  }

  // Every change goes through the scene parser, exactly as the same --set would: a bad value is
  // reported in the panel and not applied.
  void assign(const PanelRequests::Assignment& a) {
    std::vector<std::pair<std::string, std::string>> next = panel_;
    bool replaced = false;
    for (auto& entry : next) {
      if (entry.first == a.path) {
        entry.second = a.value;
        replaced = true;
      }
    }
    if (!replaced) next.emplace_back(a.path, a.value);
    try {
      Scene scene = load(phase_, next);
      panel_ = std::move(next);
      message_.clear();
      if (a.restart) {
        scene_ = std::move(scene);
        restart();
      } else {
        const bool watched = freeFlight_->body() == selectedBodyId(*world_, scene.view.selected) && scene_.view.plots == scene.view.plots &&
                             scene_.view.plotSelected == scene.view.plotSelected;
        scene_.view = scene.view;
        if (!watched) watchFreeFlight();
      }
    } catch (const InputError& e) {
      message_ = e.what();
    }
  }

  void switchPhase(std::size_t phase) {
    try {
      scene_ = load(phase, panel_);
      phase_ = phase;
    } catch (const InputError& e) {
      // The panel's assignments may name bodies the other phase lacks: start it from its file.
      scene_ = load(phase, {});
      phase_ = phase;
      panel_.clear();
      message_ = std::string("settings dropped for this phase: ") + e.what();
    }
    orbit_.reset();
    restart();
  }

  std::string commandLine() const {
    std::string line = "rbsim run " + shellQuoted(source_.files[phase_]);
    for (const std::string& o : overrides(panel_)) line += " --set " + shellQuoted(o);
    return line;
  }

  void startRecording() {
    const std::string stem = std::filesystem::path(source_.files[phase_]).stem().string();
    int n = 1;
    do {
      recordingPath_ = "videos/window-" + stem + "-" + std::to_string(n++) + ".mp4";
    } while (std::filesystem::exists(recordingPath_));
    render::SinkOptions sink;
    sink.videoPath = recordingPath_;
    sink.fps = scene_.view.fps;
    sink.width = scene_.view.width;
    sink.height = scene_.view.height;
    recorder_ = std::make_unique<render::FrameSink>(sink);
  }

  void stopRecording() {
    recorder_->finish();
    message_ = "recorded " + recordingPath_ + " (" + std::to_string(recorder_->frames()) + " frames)";
    if (!options_.quiet) std::printf("%s\n", message_.c_str());
    recorder_.reset();
  }

  struct Drag {
    SpringId spring;
    Vec3 planePoint = Vec3::Zero();   // the grabbed point: the anchor moves in the plane
    Vec3 planeNormal = Vec3::UnitZ(); // through it, facing the camera
  };

  SceneSource source_;
  WindowOptions options_;
  std::size_t phase_ = 0;
  std::vector<std::pair<std::string, std::string>> panel_;  // scene-key assignments made in the window
  Scene scene_;
  std::unique_ptr<World> world_;
  std::optional<FreeFlightError> freeFlight_;  // the selected body's error against the exact spin
  std::optional<TimePlots> plots_;           // view.plots, from the selected body's watch on

  void watchFreeFlight() {
    freeFlight_.emplace(selectedBodyId(*world_, scene_.view.selected));
    freeFlight_->observe(*world_);
    plots_.emplace(singleWorldPhase(scene_));
  }
  double playhead_ = 0.0;  // the video frame shown next [frames]; moves by speed_ a frame
  double speed_ = 1.0;
  double shownRate_ = 1.0;  // simulated seconds per real second, smoothed
  X11Window* window_ = nullptr;  // while run() has one open
  std::vector<SceneEntry> scenes_ = shippedScenes();
  bool paused_ = false;
  std::optional<OrbitCamera> orbit_;  // unset until the user moves the camera
  std::optional<Drag> drag_;
  bool orbitingWithLeft_ = false;
  int lastX_ = -1, lastY_ = -1;
  PlotHistory history_;
  std::unique_ptr<render::FrameSink> recorder_;
  std::string recordingPath_;
  std::string message_;
};

void runWindow(const SceneSource& source, const WindowOptions& options) {
  Session session(source, options);
  session.run();
}

}  // namespace rbsim::app
