#include "cli/flags.h"

#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "cli/flag_values.h"
#include "export/gltf_file.h"
#include "render/gl_context.h"
#include "render/png_file.h"
#include "window/control_panel.h"

namespace rbsim::app {
namespace {

// --trace-every past the most steps a scene may have (world.steps) would trace step 0 alone.
constexpr std::uint64_t kMaxTraceEvery = 1'000'000'000;  // [steps]
// --window-frames: 1e9 frames is 190 days at 60 fps; more is surely a typo.
constexpr std::uint64_t kMaxWindowFrames = 1'000'000'000;  // [frames]

}  // namespace

void Flags::attach(CLI::App& cmd, FlagSet set) {
  // An empty value would otherwise read as "flag not given": the flag would be ignored silently.
  // (The validator's name is left empty so that help shows the value's type alone.)
  const CLI::Validator nonEmpty([](const std::string& value) { return value.empty() ? "expected a non-empty value" : ""; },
                                "");
  const bool simulate = set == FlagSet::Simulate;
  auto option = [&](const char* name, std::string& value, const char* type, const std::string& help) {
    cmd.add_option(name, value, help)->type_name(type)->check(nonEmpty);
  };
  option("--frames", run.framesDir, "DIR", "write PNG frames into this folder");
  option("--video", run.videoPath, "FILE.mp4", "write the MP4 here (default videos/<name>.mp4)");
  option("--png-level", pngLevel, "0-9", "zlib level of the --frames PNGs: 0 stored (fastest) to 9 smallest; default 1");
  option("--trace", run.tracePath, "FILE.csv", "write every body's state, step by step, as CSV");
  option("--trace-every", traceEvery, "K", "with --trace: every K-th step, K from 1 to 1e9");
  option("--gltf", run.gltfPath, "FILE.glb",
         "write the bodies' meshes and their motion at every frame as glTF 2.0 (.glb, or .gltf for JSON), with or without --no-render");
  if (simulate) {
    option("--record", run.recordPath, "FILE.rbrec", "record every step's state, for `rbsim replay`");
    option("--steps", steps, "N", "number of steps per scene (world.steps)");
    option("--dt", dt, "SECONDS", "time step (world.dt)");
    option("--integrator", integrator, "NAME", "integrator (world.integrator); `rbsim list` names them");
    option("--inertia", inertia, "cube|exact", "default inertia method (world.inertia)");
    option("--particle-integrator", particleIntegrator, "NAME",
           "explicit-euler|semi-implicit-euler, for particle systems naming none (world.particle_integrator)");
    option("--compare", compare, "KEY=V1,V2[,...]",
           "run the scene once per value of any scene key, side by side in one frame, e.g. "
           "world.integrator=euler-quat,dlm");
  }
  option("--fps", fps, "FPS", "frames per simulated second (view.fps)");
  option("--size", size, "WxH", "image size in pixels (view.size)");
  cmd.add_option("--set", sets,
                 simulate ? "override any scene key, e.g. bodies.box.mass=2 (repeatable)"
                          : "override a view key, e.g. view.camera.distance=8 (repeatable; the motion is recorded)")
      ->type_name("KEY=VALUE")
      ->check(nonEmpty);
  option("--plot", plot, "Q1,Q2,...",
         "time plots (view.plots) of ke, pe, E, |P|, |L|, contacts, error, drift; of the whole scene, or of the "
         "selected body with --set view.plot_of=selected");
  cmd.add_flag("--no-render", noRender, "simulate only: no frames, no video");
  cmd.add_flag("--no-overlay", noOverlay, "hide the variables panel (view.overlay=false)");
  cmd.add_flag("--quiet", run.quiet, "print nothing on success");
  cmd.add_flag("--window", window, "open an X11 window with controls instead of writing a video");
  option("--window-frames", windowFrames, "N", "with --window: close after N frames (scripted runs), N >= 1");
  option("--screenshot", windowOptions.screenshot, "FILE.png", "with --window: PNG of the window's last frame");
  if (simulate) {
    option("--speed", speed, "X",
           "with --window: playback speed, simulated seconds per second, 0.1 (slow motion) to 4; default 1, real time");
  }
  option("--gl", gl, render::glBackendChoices().c_str(),
         std::string("off-screen OpenGL (default ") + render::glBackendName(render::defaultGlBackend()) +
             "; both are Mesa's llvmpipe, egl on the surfaceless platform)");
}

RunOptions Flags::finish(const std::string& defaultVideo) {
  if (!run.gltfPath.empty()) gltfFormatOf(run.gltfPath);  // its name, before any scene is read
  if (!pngLevel.empty()) {
    run.pngLevel = static_cast<int>(parseFlagInteger(
        "--png-level", pngLevel, render::kMinPngLevel, render::kMaxPngLevel,
        "a zlib level (0: stored, fastest; 9: smallest)"));
  }
  if (!traceEvery.empty()) {
    run.traceEvery = parseFlagInteger("--trace-every", traceEvery, 1, kMaxTraceEvery,
                                      "a step interval (1: every step)");
  }
  if (!windowFrames.empty()) {
    windowOptions.frames = parseFlagInteger("--window-frames", windowFrames, 1, kMaxWindowFrames,
                                            "a number of frames to show");
  }
  if (!gl.empty()) {
    const std::optional<render::GlBackend> backend = render::parseGlBackend(gl);
    if (!backend) throw InputError("", "--gl " + gl, "expected " + render::glBackendChoices());
    run.glBackend = *backend;
    windowOptions.glBackend = *backend;
  }
  if (!speed.empty()) {
    windowOptions.speed = parseFlagNumber("--speed", speed, kMinPlaybackSpeed, kMaxPlaybackSpeed,
                                          "simulated seconds per second (1: real time)");
  }
  refuseIgnoredFlags();
  auto add = [&](const std::string& key, const std::string& value, const std::string& flag) {
    if (value.empty()) return;
    run.overrides.push_back(key + "=" + value);
    keyFlags[key] = flag;
  };
  add("world.dt", dt, "--dt " + dt);
  add("world.steps", steps, "--steps " + steps);
  add("world.integrator", integrator.empty() ? "" : "\"" + integrator + "\"", "--integrator " + integrator);
  add("world.inertia", inertia.empty() ? "" : "\"" + inertia + "\"", "--inertia " + inertia);
  add("world.particle_integrator", particleIntegrator.empty() ? "" : "\"" + particleIntegrator + "\"",
      "--particle-integrator " + particleIntegrator);
  add("view.fps", fps, "--fps " + fps);
  if (!size.empty()) {
    const auto [width, height] = parseImageSize("--size", size);
    add("view.size", "[" + std::to_string(width) + "," + std::to_string(height) + "]", "--size " + size);
  }
  if (noOverlay) add("view.overlay", "false", "--no-overlay");
  if (!plot.empty()) {
    nlohmann::json names = nlohmann::json::array();
    std::size_t start = 0;
    for (std::size_t comma; (comma = plot.find(',', start)) != std::string::npos; start = comma + 1) {
      names.push_back(plot.substr(start, comma - start));
    }
    names.push_back(plot.substr(start));
    add("view.plots", names.dump(), "--plot " + plot);
  }
  if (!compare.empty()) {
    add("compare", parseCompareFlag(compare), "--compare " + compare);
    for (const char* field : {"compare.key", "compare.values"}) keyFlags[field] = "--compare " + compare;
  }
  for (const std::string& s : sets) {
    run.overrides.push_back(s);
    keyFlags.erase(s.substr(0, s.find('=')));  // a later --set of the key wins over the flag
  }
  run.render = !noRender;
  if (run.videoPath.empty() && run.render) run.videoPath = defaultVideo;
  return run;
}

// A flag that the others make pointless would be ignored without a word: refused instead.
void Flags::refuseIgnoredFlags() const {
  const std::pair<const char*, bool> imageFlags[] = {
      {"--frames", !run.framesDir.empty()}, {"--video", !run.videoPath.empty()}, {"--png-level", !pngLevel.empty()}};
  const std::pair<const char*, bool> runFlags[] = {{"--trace", !run.tracePath.empty()},
                                                   {"--trace-every", !traceEvery.empty()},
                                                   {"--gltf", !run.gltfPath.empty()},
                                                   {"--no-render", noRender}};
  for (const auto& [flag, given] : imageFlags) {
    if (given && noRender) {
      throw InputError("", std::string(flag) + " with --no-render", "contradictory: --no-render writes no images");
    }
    if (given && window) {
      throw InputError("", std::string(flag) + " with --window",
                       "not allowed: the window writes no files (its record button writes videos/window-*.mp4)");
    }
  }
  for (const auto& [flag, given] : runFlags) {
    if (given && window) {
      throw InputError("", std::string(flag) + " with --window", "not allowed: --window shows the scene live and writes no trace, glTF or video");
    }
  }
  if (!gl.empty() && noRender) {
    throw InputError("", "--gl with --no-render", "contradictory: --no-render makes no OpenGL context");
  }
  if (!pngLevel.empty() && run.framesDir.empty()) {
    throw InputError("", "--png-level without --frames", "it sets the PNG frames' compression; add --frames DIR");
  }
  if (!traceEvery.empty() && run.tracePath.empty()) {
    throw InputError("", "--trace-every without --trace", "it only thins the trace; add --trace FILE.csv");
  }
  for (const auto& [flag, given] : {std::pair<const char*, bool>{"--window-frames", !windowFrames.empty()},
                                    std::pair<const char*, bool>{"--screenshot", !windowOptions.screenshot.empty()},
                                    std::pair<const char*, bool>{"--speed", !speed.empty()}}) {
    if (given && !window) throw InputError("", std::string(flag) + " without --window", "it only acts on the window; add --window");
  }
}


std::string Flags::origin(const InputError& e) const {
  const auto it = keyFlags.find(e.field());
  return it == keyFlags.end() ? "" : " (from " + it->second + ")";
}

}  // namespace rbsim::app
