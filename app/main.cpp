// The rbsim command: numbered assignment demos, scenes from files, a listing. Exit codes:
// 0 success, 2 bad input (file, field and expectation named), 1 internal error (docs/architecture.md, "Around the engine").
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "demos/demo.h"
#include "flag_values.h"
#include "record/recording.h"
#include "rbsim/integrate/integrator.h"
#include "rbsim/io/input_error.h"
#include "rbsim/particles/particle_def.h"
#include "run/output_paths.h"
#include "run/paths.h"
#include "render/offscreen_renderer.h"
#include "render/render_error.h"
#include "window/interactive.h"
#include "window/replay_window.h"
#include "window/x11_window.h"
#include "run/progress.h"
#include "run/reel.h"
#include "run/runner.h"
#include "rbsim/scene/scene.h"
#include "rbsim/integrate/simulation_error.h"

namespace {

using rbsim::InputError;
using rbsim::app::RunOptions;

// --trace-every past the most steps a scene may have (world.steps) would trace step 0 alone.
constexpr std::uint64_t kMaxTraceEvery = 1'000'000'000;  // [steps]
// --window-frames: 1e9 frames is 190 days at 60 fps; more is surely a typo.
constexpr std::uint64_t kMaxWindowFrames = 1'000'000'000;  // [frames]

// Flags shared by `demo` and `run`. Those that change the scene become --set assignments, so a
// flag and the scene key it stands for are checked by the same code.
struct Flags {
  RunOptions run;
  std::string dt, steps, fps, size, integrator, inertia, particleIntegrator;
  std::string pngLevel, traceEvery, windowFrames;  // numbers, parsed by flag_values.h
  std::string gl;                                  // off-screen GL backend, render/gl_context.h
  std::string compare;                             // KEY=V1,V2[,...]: a compare block
  std::string plot;                                // Q1,Q2,...: view.plots
  // Scene key -> the flag that set it ("view.size" -> "--size 0x0"), so an error the scene reports
  // about the key can say which flag it came from.
  std::map<std::string, std::string> keyFlags;
  bool noRender = false, noOverlay = false, window = false;
  rbsim::app::WindowOptions windowOptions;
  std::vector<std::string> sets;

  void attach(CLI::App& cmd) {
    // An empty value would otherwise read as "flag not given": the flag would be ignored silently.
    const CLI::Validator nonEmpty([](const std::string& value) { return value.empty() ? "expected a non-empty value" : ""; },
                                  "NONEMPTY");
    cmd.add_option("--frames", run.framesDir, "write PNG frames into this folder")->check(nonEmpty);
    cmd.add_option("--video", run.videoPath, "write the MP4 here (default videos/<name>.mp4)")->check(nonEmpty);
    cmd.add_option("--png-level", pngLevel,
                   "zlib level of the --frames PNGs, 0 (stored, fastest) to 9 (smallest); default 1, "
                   "see app/render/png_file.h")
        ->check(nonEmpty);
    cmd.add_option("--trace", run.tracePath, "write the per-body CSV trace here")->check(nonEmpty);
    cmd.add_option("--trace-every", traceEvery, "trace every K-th step, K from 1 to 1e9")->check(nonEmpty);
    cmd.add_option("--record", run.recordPath,
                   "record every step's state into this file, for `rbsim replay` (record/recording.h)")
        ->check(nonEmpty);
    cmd.add_option("--steps", steps, "number of steps per scene (world.steps)")->check(nonEmpty);
    cmd.add_option("--dt", dt, "time step in seconds (world.dt)")->check(nonEmpty);
    cmd.add_option("--fps", fps, "frames per simulated second (view.fps)")->check(nonEmpty);
    cmd.add_option("--size", size, "image size WxH in pixels (view.size)")->check(nonEmpty);
    cmd.add_option("--integrator", integrator, "integrator name (world.integrator); see `rbsim list`")->check(nonEmpty);
    cmd.add_option("--inertia", inertia, "cube|exact: default inertia method (world.inertia)")->check(nonEmpty);
    cmd.add_option("--particle-integrator", particleIntegrator,
                   "explicit-euler|semi-implicit-euler: of particle systems naming none (world.particle_integrator)")
        ->check(nonEmpty);
    cmd.add_option("--set", sets, "override any scene key: path=value, e.g. bodies.box.mass=2")->check(nonEmpty);
    cmd.add_option("--compare", compare,
                   "KEY=V1,V2[,...]: run the scene once per value of any scene key, drawn side by side in one "
                   "frame (a \"compare\" block), e.g. world.integrator=euler-quat,dlm")
        ->check(nonEmpty);
    cmd.add_option("--plot", plot,
                   "time plots in the frame (view.plots): a comma-separated list of ke, pe, E, |P|, |L|, "
                   "contacts, error; of the whole scene, or of the selected body with --set view.plot_of=selected")
        ->check(nonEmpty);
    cmd.add_flag("--no-render", noRender, "simulate only: no frames, no video");
    cmd.add_flag("--no-overlay", noOverlay, "hide the variables panel (view.overlay=false)");
    cmd.add_flag("--quiet", run.quiet, "print nothing on success");
    cmd.add_flag("--window", window, "open an X11 window with controls instead of writing a video");
    cmd.add_option("--window-frames", windowFrames, "with --window: close after N frames (scripted runs), N >= 1")
        ->check(nonEmpty);
    cmd.add_option("--screenshot", windowOptions.screenshot, "with --window: PNG of the window's last frame")->check(nonEmpty);
    cmd.add_option("--gl", gl,
                   "off-screen OpenGL: " + rbsim::render::glBackendChoices() + " (default " +
                       rbsim::render::glBackendName(rbsim::render::defaultGlBackend()) +
                       "; both are Mesa's llvmpipe, egl on the surfaceless platform)")
        ->check(nonEmpty);
  }

  // `framesByDefault`: `demo all` writes PNG frames without --frames (so --png-level applies).
  RunOptions finish(const std::string& defaultVideo, bool framesByDefault = false) {
    using rbsim::app::parseFlagInteger;
    if (!pngLevel.empty()) {
      run.pngLevel = static_cast<int>(parseFlagInteger(
          "--png-level", pngLevel, rbsim::render::kMinPngLevel, rbsim::render::kMaxPngLevel,
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
      const std::optional<rbsim::render::GlBackend> backend = rbsim::render::parseGlBackend(gl);
      if (!backend) throw InputError("", "--gl " + gl, "expected " + rbsim::render::glBackendChoices());
      run.glBackend = *backend;
      windowOptions.glBackend = *backend;
    }
    refuseIgnoredFlags(framesByDefault);
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
      const auto [width, height] = rbsim::app::parseImageSize("--size", size);
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
      add("compare", rbsim::app::parseCompareFlag(compare), "--compare " + compare);
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
  void refuseIgnoredFlags(bool framesByDefault) const {
    const std::pair<const char*, bool> imageFlags[] = {
        {"--frames", !run.framesDir.empty()}, {"--video", !run.videoPath.empty()}, {"--png-level", !pngLevel.empty()}};
    const std::pair<const char*, bool> runFlags[] = {{"--trace", !run.tracePath.empty()},
                                                     {"--trace-every", !traceEvery.empty()},
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
        throw InputError("", std::string(flag) + " with --window", "not allowed: --window shows the scene live and writes no trace or video");
      }
    }
    if (!gl.empty() && noRender) {
      throw InputError("", "--gl with --no-render", "contradictory: --no-render makes no OpenGL context");
    }
    if (!pngLevel.empty() && run.framesDir.empty() && !framesByDefault) {
      throw InputError("", "--png-level without --frames", "it sets the PNG frames' compression; add --frames DIR");
    }
    if (!traceEvery.empty() && run.tracePath.empty()) {
      throw InputError("", "--trace-every without --trace", "it only thins the trace; add --trace FILE.csv");
    }
    for (const auto& [flag, given] : {std::pair<const char*, bool>{"--window-frames", !windowFrames.empty()},
                                      std::pair<const char*, bool>{"--screenshot", !windowOptions.screenshot.empty()}}) {
      if (given && !window) throw InputError("", std::string(flag) + " without --window", "it only acts on the window; add --window");
    }
  }

  // The flag behind a scene error's field, as " (from --size 0x0)", or "" when no flag set it.
  std::string origin(const InputError& e) const {
    const auto it = keyFlags.find(e.field());
    return it == keyFlags.end() ? "" : " (from " + it->second + ")";
  }
};

// Everything printed on stdout (the summary, `list`) is checked too: `rbsim run ... > /dev/full`
// must not report success.
int finishStdout(int code) {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int why = errno;
    std::fprintf(stderr, "rbsim: error: standard output: cannot write the summary (%s)\n",
                 why != 0 ? std::strerror(why) : "write error");
    return 2;
  }
  return code;
}

int parseDemoNumber(const std::string& text) {
  std::size_t used = 0;
  int number = 0;
  try {
    number = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size()) {
    throw InputError("", "demo " + text, "expected a demo number (see `rbsim list`) or `all`");
  }
  return number;
}

int listEverything() {
  std::printf("demos:\n");
  for (const rbsim::app::Demo& demo : rbsim::app::allDemos()) {
    std::printf("  %d  %-14s %s\n", demo.number, demo.name.c_str(), demo.description.c_str());
  }
  std::printf("integrators:\n");
  for (const std::string& name : rbsim::integratorNames()) std::printf("  %s\n", name.c_str());
  std::printf("inertia methods:\n  cube\n  exact\n");
  std::printf("particle integrators (particles[].integrator):\n");
  for (const std::string& name : rbsim::particleIntegratorNames()) std::printf("  %s\n", name.c_str());
  std::printf("data folders (RBSIM_ASSET_DIR, RBSIM_SHADER_DIR, or beside the executable):\n  assets   %s\n  shaders  %s\n",
              rbsim::app::assetDir().c_str(), rbsim::render::defaultShaderDir().c_str());
  return 0;
}

// `rbsim demo all`: every demo into videos/<name>.mp4 and, after title cards, into one reel, all
// at 1280x720 and 60 fps. Flags that choose one phase, one output file, a window, another format
// or no rendering contradict that, so they are refused rather than half-applied.
int renderAllDemos(const CLI::App& demo, Flags& flags) {
  for (const char* name : {"--phase", "--video", "--trace", "--trace-every", "--fps", "--size", "--no-render", "--window",
                           "--window-frames", "--screenshot", "--record"}) {
    if (demo.get_option(name)->count() > 0) {
      throw InputError("", std::string(name) + " with `demo all`",
                       "not allowed: `demo all` renders every demo at 1280x720, 60 fps into videos/<name>.mp4 and "
                       "videos/rbsim-demos.mp4; use `demo N` for one demo");
    }
  }
  rbsim::app::ReelOptions reel;
  const RunOptions run = flags.finish("", true);
  reel.overrides = run.overrides;
  reel.quiet = run.quiet;
  reel.pngLevel = run.pngLevel;
  reel.glBackend = run.glBackend;
  if (!run.framesDir.empty()) reel.framesBase = run.framesDir;
  const rbsim::app::ReelPlan plan = rbsim::app::planReel(rbsim::app::allDemos(), reel);
  if (!reel.quiet) {
    std::fprintf(stderr, "rbsim: %zu demos, %llu frames (%s of video at %dx%d, %d fps)\n", plan.demos.size(),
                 static_cast<unsigned long long>(plan.totalFrames),
                 rbsim::app::formatClock(static_cast<double>(plan.totalFrames) / reel.fps).c_str(), reel.width,
                 reel.height, reel.fps);
  }
  const rbsim::app::ReelResult result = rbsim::app::renderReel(plan, reel);
  rbsim::app::printReelSummary(result, reel);
  return finishStdout(0);
}

// `rbsim replay FILE`: the recording's phases rebuilt from the scene files it holds, with its own
// overrides and then the view keys given now, drawn from the recorded states (record/recording.h).
int replayRecording(const std::string& path, Flags& flags) {
  const RunOptions options = flags.finish("videos/" + std::filesystem::path(path).stem().string() + "_replay.mp4");
  if (!options.recordPath.empty()) throw InputError("", "--record with replay", "a replay records nothing: it is drawn from a recording");
  for (const std::string& assignment : options.overrides) {
    const std::string key = assignment.substr(0, assignment.find('='));
    if (key.rfind("view.", 0) != 0 && key != "view") {
      throw InputError("", key, "a replay shows the recorded motion: only view keys (camera, size, fps, overlay, plots) may change");
    }
  }
  rbsim::app::requireRegularInput({"recording", path}, "a recording written by --record");
  rbsim::app::RecordReader reader(path);
  std::vector<std::string> overrides = reader.header().overrides;
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  std::vector<rbsim::app::Phase> phases;
  for (std::size_t i = 0; i < reader.header().phases.size(); ++i) {
    const rbsim::app::RecordedPhase& p = reader.header().phases[i];
    reader.checkFiles(i);
    phases.push_back(rbsim::app::parsePhaseText(p.text, p.file, p.baseDir, overrides));
    // Contacts and boxes come from collision detection, which a replay does not run.
    bool dropped = false;
    for (rbsim::app::PhaseWorld& w : phases.back().worlds) {
      dropped = dropped || w.scene.view.contacts || w.scene.view.aabbs;
      w.scene.view.contacts = w.scene.view.aabbs = false;
    }
    if (dropped && !options.quiet) {
      std::fprintf(stderr, "rbsim: replay: %s draws contacts or AABBs, which are not recorded; they are left out\n",
                   p.file.c_str());
    }
  }
  if (flags.window) {
    flags.windowOptions.quiet = options.quiet;
    if (!flags.windowOptions.screenshot.empty()) {
      rbsim::app::checkOutputPaths({{"--screenshot", flags.windowOptions.screenshot}}, {{"recording", path}}, "");
    }
    rbsim::app::runReplayWindow(phases, reader, path, flags.windowOptions);
    return finishStdout(0);
  }
  const rbsim::app::RunSummary summary = rbsim::app::runPhases(phases, options, reader.header().title, {}, &reader);
  rbsim::app::printSummary(summary, options);
  return finishStdout(0);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rbsim: rigid-body simulator with numbered coursework demos, rendered off-screen"};
  app.require_subcommand(1);

  std::string demoArgument;
  std::string demoPhase;  // empty: every phase
  Flags demoFlags;
  CLI::App* demo = app.add_subcommand("demo", "run numbered assignment demo N into videos/");
  demo->add_option("N", demoArgument, "demo number (see `rbsim list`), or `all`: every demo, and the reel "
                                      "videos/rbsim-demos.mp4")
      ->required();
  demo->add_option("--phase", demoPhase, "play only phase K (1 = the first scene) -> videos/<name>_K.mp4");
  demoFlags.attach(*demo);

  std::string scenePath;
  Flags runFlags;
  CLI::App* run = app.add_subcommand("run", "run a scene file");
  run->add_option("SCENE", scenePath, "scene JSON file")->required();
  runFlags.attach(*run);

  std::string recordingPath;
  Flags replayFlags;
  CLI::App* replay = app.add_subcommand("replay", "draw a recording (--record) again without simulating: another camera, "
                                                  "size, overlay or plots through view keys; with --window, a timeline to scrub");
  replay->add_option("RECORDING", recordingPath, "a file written by --record")->required();
  replayFlags.attach(*replay);

  app.add_subcommand("list", "list demos, integrators and inertia methods");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  try {
    if (app.got_subcommand("list")) return finishStdout(listEverything());
    std::vector<rbsim::app::Phase> phases;
    std::vector<std::string> files;
    std::string title;
    RunOptions options;
    Flags& flags = app.got_subcommand("demo") ? demoFlags : app.got_subcommand("replay") ? replayFlags : runFlags;
    if (app.got_subcommand("demo") && demoArgument == "all") return renderAllDemos(*demo, demoFlags);
    if (app.got_subcommand("replay")) return replayRecording(recordingPath, replayFlags);
    if (app.got_subcommand("demo")) {
      const int demoNumber = parseDemoNumber(demoArgument);
      const rbsim::app::Demo* chosen = rbsim::app::findDemo(demoNumber);
      if (!chosen) {
        throw InputError("", "demo " + std::to_string(demoNumber), "no such demo; `rbsim list` shows them");
      }
      std::vector<std::string> phases = chosen->scenes;
      std::string video = "videos/" + chosen->name + ".mp4";
      if (demo->get_option("--phase")->count() > 0) {
        const std::string count = std::to_string(phases.size());
        const std::uint64_t phase = rbsim::app::parseFlagInteger(
            "--phase " + demoPhase, demoPhase, 1, phases.size(),
            "a phase number (demo " + std::to_string(demoNumber) + " has " + count + " phases)");
        phases = {phases[phase - 1]};
        video = "videos/" + chosen->name + "_" + std::to_string(phase) + ".mp4";
      }
      options = demoFlags.finish(video);
      for (const std::string& file : phases) files.push_back(rbsim::app::assetDir() + "/scenes/" + file);
      title = "Demo " + std::to_string(chosen->number) + ": " + chosen->name;
    } else {
      options = runFlags.finish("videos/" + std::filesystem::path(scenePath).stem().string() + ".mp4");
      files.push_back(scenePath);
    }
    if (flags.window) {
      if (!options.recordPath.empty()) {
        throw InputError("", "--record with --window", "not allowed: a window session is not recorded (its Record button writes a video)");
      }
      flags.windowOptions.quiet = options.quiet;
      if (!flags.windowOptions.screenshot.empty()) {
        std::vector<rbsim::app::NamedFile> inputs;
        for (const std::string& file : files) inputs.push_back({"scene", file});
        rbsim::app::checkOutputPaths({{"--screenshot", flags.windowOptions.screenshot}}, inputs, "");
      }
      rbsim::app::runWindow({files, options.overrides, title}, flags.windowOptions);
      return finishStdout(0);
    }
    for (const std::string& file : files) phases.push_back(rbsim::app::loadPhase(file, options.overrides));
    const rbsim::app::RunSummary summary = rbsim::app::runPhases(phases, options, title);
    rbsim::app::printSummary(summary, options);
    return finishStdout(0);
  } catch (const InputError& e) {
    // Only the chosen subcommand's flags are filled in, so at most one of these names a flag.
    std::fprintf(stderr, "rbsim: error: %s%s%s%s\n", e.what(), demoFlags.origin(e).c_str(), runFlags.origin(e).c_str(),
                 replayFlags.origin(e).c_str());
    return 2;
  } catch (const rbsim::SimulationError& e) {
    std::fprintf(stderr, "rbsim: error: the simulation diverged: %s\n", e.what());
    return 2;
  } catch (const rbsim::app::WindowError& e) {
    std::fprintf(stderr, "rbsim: error: %s\n", e.what());
    return 2;
  } catch (const rbsim::render::RenderError& e) {
    std::fprintf(stderr, "rbsim: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rbsim: internal error: %s\n", e.what());
    return 1;
  }
}
