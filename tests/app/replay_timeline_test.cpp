// The replay window's timeline (app/window/replay_timeline.h): any frame of a recording, shown in
// any order, holds exactly the worlds a run stepped to that frame holds, and the plots the run
// drew then, bodies spawned since the scene's start included; a recording larger than the
// timeline may keep is refused before the window opens.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "run/paths.h"
#include "rbsim/io/input_error.h"
#include "record/recording.h"
#include "window/replay_timeline.h"
#include "run/phase.h"
#include "run/plot_history.h"
#include "run/runner.h"

namespace rbsim::app {
namespace {

namespace fs = std::filesystem;

void expectSameWorld(const World& a, const World& b, const std::string& where) {
  ASSERT_EQ(a.stepCount(), b.stepCount()) << where;
  ASSERT_EQ(a.bodies().size(), b.bodies().size()) << where;
  for (std::size_t i = 0; i < a.bodies().size(); ++i) {
    const RigidBody& x = a.bodies()[i];
    const RigidBody& y = b.bodies()[i];
    EXPECT_EQ(x.position(), y.position()) << where << " body " << i;
    EXPECT_EQ(x.orientation().coeffs(), y.orientation().coeffs()) << where << " body " << i;
    EXPECT_EQ(x.velocity(), y.velocity()) << where << " body " << i;
    EXPECT_EQ(x.angularVelocity(), y.angularVelocity()) << where << " body " << i;
  }
}

TEST(ReplayTimeline, AnyFrameInAnyOrderIsTheRunAtThatFrame) {
  const fs::path dir = fs::temp_directory_path() / ("rbsim_timeline_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "run.rbrec").string();
  // Two phases: three integrators side by side with plots, then a box pushed at a point.
  const std::vector<std::string> overrides = {"world.steps=120", "view.size=[160,90]", "view.fps=30"};
  std::vector<Phase> phases;
  for (const char* scene : {"assignment2_e_integrators.json", "assignment2_c_force_at_point.json"}) {
    phases.push_back(loadPhase(assetDir() + "/scenes/" + scene, overrides));
  }
  RunOptions options;
  options.quiet = true;
  options.render = false;
  options.overrides = overrides;
  options.recordPath = file;
  runPhases(phases, options, "timeline test");

  RecordReader reader(file);
  ReplayTimeline timeline(phases, reader, file);
  const std::size_t first = frameCount(phases[0]), second = frameCount(phases[1]);
  ASSERT_EQ(timeline.frames(), first + second);
  EXPECT_EQ(timeline.current(), 0u);

  // Each frame against its phase's worlds stepped from the start to that frame's steps.
  for (const std::size_t f : {std::size_t{37}, std::size_t{3}, first + second / 2, std::size_t{0}, first - 1, std::size_t{37}, first}) {
    timeline.show(f);
    const std::size_t p = f < first ? 0 : 1, local = f < first ? f : f - first;
    EXPECT_EQ(timeline.phaseIndex(), p);
    const Phase& phase = phases[p];
    std::vector<World> worlds;
    for (const PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
    TimePlots plots(phase);
    for (std::uint64_t g = 0; g <= local; ++g) {
      for (std::size_t k = 0; k < worlds.size(); ++k) {
        const Scene& scene = phase.worlds[k].scene;
        const std::uint64_t target = std::min(stepOfFrame(g, scene.view.fps, scene.settings.timeStep), scene.stepCount());
        while (worlds[k].stepCount() < target) worlds[k].step();
      }
      if (!plots.empty()) plots.sample(worlds, nullptr);
    }
    ASSERT_EQ(timeline.worlds().size(), worlds.size());
    for (std::size_t k = 0; k < worlds.size(); ++k) expectSameWorld(timeline.worlds()[k], worlds[k], "frame " + std::to_string(f));
    // The plots as the run drew them at this frame (the error plot aside: it needs every step).
    const std::vector<render::OverlayPlot> shown = timeline.plots(), expected = plots.plots();
    ASSERT_EQ(shown.size(), expected.size());
    for (std::size_t i = 0; i < shown.size(); ++i) {
      if (shown[i].title.find("exact") != std::string::npos) continue;
      EXPECT_EQ(shown[i].tMax, expected[i].tMax);
      EXPECT_EQ(shown[i].times, expected[i].times) << shown[i].title << " at frame " << f;
      EXPECT_EQ(shown[i].values, expected[i].values) << shown[i].title << " at frame " << f;
    }
  }
  fs::remove_all(dir);
}

// Ragdolls spawned at steps 1 and 61 (machinery_rain, dt 1/60 s, a burst a second): a frame
// before the first burst, between the bursts and after the second, shown in scrambled order,
// holds the bodies the run had then, with their names and meshes.
TEST(ReplayTimeline, FramesOfASceneWhoseBodiesChangeHoldTheRunsBodies) {
  const fs::path dir = fs::temp_directory_path() / ("rbsim_timeline_spawn_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "run.rbrec").string();
  const std::vector<std::string> overrides = {"world.steps=80", "view.size=[160,90]", "view.fps=30"};
  const std::vector<Phase> phases = {loadPhase(assetDir() + "/scenes/machinery_rain.json", overrides)};
  RunOptions options;
  options.quiet = true;
  options.render = false;
  options.overrides = overrides;
  options.recordPath = file;
  runPhases(phases, options, "timeline test");

  RecordReader reader(file);
  ReplayTimeline timeline(phases, reader, file);
  const Scene& scene = phases[0].scene();
  for (const std::size_t f : {std::size_t{35}, std::size_t{0}, std::size_t{20}, std::size_t{1}, std::size_t{39}, std::size_t{10}}) {
    timeline.show(f);
    World run = buildWorld(scene);
    const std::uint64_t target = std::min(stepOfFrame(f, scene.view.fps, scene.settings.timeStep), scene.stepCount());
    while (run.stepCount() < target) run.step();
    const World& shown = timeline.worlds()[0];
    expectSameWorld(shown, run, "frame " + std::to_string(f));
    for (std::size_t i = 0; i < run.bodies().size() && i < shown.bodies().size(); ++i) {
      EXPECT_EQ(shown.bodies()[i].name(), run.bodies()[i].name()) << "frame " << f;
      EXPECT_EQ(shown.bodies()[i].mesh().vertices, run.bodies()[i].mesh().vertices) << "frame " << f << " body " << i;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rbsim::app
