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
#include "cli/cli_messages.h"
#include "cli/flags.h"
#include "run/scene_catalogue.h"
#include "cli/flag_values.h"
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
#include "rbsim/scene/scene_schema.h"
#include "rbsim/integrate/simulation_error.h"

namespace {

using rbsim::InputError;
using rbsim::app::Flags;
using rbsim::app::FlagSet;
using rbsim::app::RunOptions;

// Everything printed on stdout (the summary, `list`, --version, --help) is checked too:
// `rbsim run ... > /dev/full` must not report success. `what` names what was printed.
int finishStdout(int code, const char* what = "the summary") {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int why = errno;
    std::fprintf(stderr, "rbsim: error: standard output: cannot write %s (%s)\n", what,
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
  std::printf("scenes in %s/scenes (rbsim run NAME):\n", rbsim::app::assetDir().c_str());
  for (const rbsim::app::SceneEntry& scene : rbsim::app::shippedScenes()) {
    std::printf("  %-32s %s\n", scene.name.c_str(), scene.title.c_str());
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
                           "--window-frames", "--screenshot", "--record", "--gltf"}) {
    if (demo.get_option(name)->count() > 0) {
      throw InputError("", std::string(name) + " with `demo all`",
                       "not allowed: `demo all` renders every demo at 1280x720, 60 fps into videos/<name>.mp4 and "
                       "videos/rbsim-demos.mp4; use `demo N` for one demo");
    }
  }
  rbsim::app::ReelOptions reel;
  const RunOptions run = flags.finish("");
  reel.overrides = run.overrides;
  reel.quiet = run.quiet;
  reel.pngLevel = run.pngLevel;
  reel.glBackend = run.glBackend;
  if (!run.framesDir.empty()) {
    reel.framesBase = run.framesDir;
    reel.writeFrames = true;
  }
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
  app.set_version_flag("--version", rbsim::app::versionText(), "print the version and the commit it was built from");
  rbsim::app::formatParseErrors(app);

  std::string demoArgument;
  std::string demoPhase;  // empty: every phase
  Flags demoFlags;
  CLI::App* demo = app.add_subcommand("demo", "run numbered assignment demo N into videos/");
  demo->add_option("N", demoArgument, "demo number (see `rbsim list`), or `all`: every demo, and the reel "
                                      "videos/rbsim-demos.mp4")
      ->type_name("N|all")
      ->required();
  demo->add_option("--phase", demoPhase, "play only phase K (1 = the first scene) -> videos/<name>_K.mp4")->type_name("K");
  demoFlags.attach(*demo, FlagSet::Simulate);

  std::string scenePath;
  Flags runFlags;
  CLI::App* run = app.add_subcommand("run", "run a scene file");
  run->add_option("SCENE", scenePath, "a scene file, or the name of a shipped scene (`rbsim list`)")
      ->type_name("FILE|NAME")
      ->required();
  runFlags.attach(*run, FlagSet::Simulate);

  std::string recordingPath;
  Flags replayFlags;
  CLI::App* replay = app.add_subcommand("replay", "draw a recording (--record) again without simulating: another camera, "
                                                  "size, overlay or plots through view keys; with --window, a timeline to scrub");
  replay->add_option("RECORDING", recordingPath, "a file written by --record")->type_name("FILE.rbrec")->required();
  replayFlags.attach(*replay, FlagSet::Replay);

  app.add_subcommand("list", "list the demos, the shipped scenes, integrators and inertia methods");
  app.add_subcommand("schema", "print the JSON Schema of scene files (docs/scene.schema.json), for editors");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --version and --help end the parse with code 0, their text on stdout.
    const int code = app.exit(e);
    return code == 0 ? finishStdout(0, "the version or help text") : 2;
  }

  try {
    if (app.got_subcommand("list")) return finishStdout(listEverything());
    if (app.got_subcommand("schema")) {
      std::printf("%s\n", rbsim::sceneSchema().dump(2).c_str());
      return finishStdout(0, "the schema");
    }
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
      files.push_back(rbsim::app::resolveScene(scenePath));
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
  } catch (const rbsim::StepLimitError& e) {  // the scene asks more of a step than it holds: not a divergence
    std::fprintf(stderr, "rbsim: error: %s\n", e.what());
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
