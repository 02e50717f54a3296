// Every phase of every numbered demo loads from assets/scenes/ and simulates a second without
// the state leaving finite values, and runs the same twice (the determinism hash). A compared
// phase (a "compare" block, app/run/phase.h) gives each World its own value and nothing else.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../sanitized_build.h"
#include "demos/demo.h"
#include "rbsim/io/input_error.h"
#include "run/paths.h"
#include "render/pane_layout.h"
#include "run/compare_view.h"
#include "run/phase.h"
#include "run/runner.h"
#include "rbsim/scene/scene.h"
#include "rbsim/world/world.h"

namespace rbsim::app {

// The demos' test names and messages say "demo 5", not the struct's bytes.
void PrintTo(const Demo& demo, std::ostream* os) { *os << "demo " << demo.number; }

namespace {

// One test a demo, so that ctest shares the demos among its jobs.
class DemoScenes : public testing::TestWithParam<Demo> {};

TEST_P(DemoScenes, EveryPhaseLoadsSimulatesAndRepeatsBitForBit) {
  for (const std::string& file : GetParam().scenes) {
    const Phase phase = loadPhase(assetDir() + "/scenes/" + file);
    for (const PhaseWorld& world : phase.worlds) {
      const Scene& scene = world.scene;
      // Under the sanitizers the second World is a copy of the first, not a second build (tests/
      // sanitized_build.h): building demo 7's soft bodies twice took half of its 35 s there.
      World first = buildWorld(scene);
      World second = test::kSanitizedBuild ? World(first) : buildWorld(scene);
      // A second each; a tenth under the sanitizers, where demo 7's soft bodies took 70 s for a
      // quarter: the steps after loading are what the sanitizers check.
      const double seconds = test::kSanitizedBuild ? 0.1 : 1.0;
      const int steps = static_cast<int>(std::lround(seconds / scene.settings.timeStep));
      for (int s = 0; s < steps; ++s) {
        first.step();
        second.step();
      }
      EXPECT_EQ(first.stateHash(), second.stateHash()) << file << " " << world.label;
      for (const RigidBody& b : first.bodies()) EXPECT_TRUE(b.position().allFinite()) << file << " " << b.name();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryDemo, DemoScenes, testing::ValuesIn(allDemos()),
                         [](const testing::TestParamInfo<Demo>& info) { return "demo" + std::to_string(info.param.number); });

TEST(DemoScenesCount, TheDemosHaveAtLeastTwelvePhases) {
  std::size_t phases = 0;
  for (const Demo& demo : allDemos()) phases += demo.scenes.size();
  EXPECT_GE(phases, 12u);
}

// Demo 5's last phase: the same 230 boxes (a column of 20, a pyramid of 210; bench/stack_layout.h)
// once with PGS and once with soft step. Each World gets its value of world.solver through the
// --set path, the two are identical at t = 0 in everything else, and the value changes the run.
TEST(ComparedPhase, EachWorldGetsItsOwnSolverAndIsOtherwiseTheSame) {
  const Phase phase = loadPhase(assetDir() + "/scenes/contact_solvers.json");
  ASSERT_TRUE(phase.compared());
  EXPECT_EQ(phase.compareKey, "world.solver");
  ASSERT_EQ(phase.worlds.size(), 2u);
  EXPECT_EQ(phase.worlds[0].label, "PGS");
  EXPECT_EQ(phase.worlds[1].label, "soft step");

  World pgs = buildWorld(phase.worlds[0].scene), soft = buildWorld(phase.worlds[1].scene);
  EXPECT_EQ(pgs.settings().solver, Settings::ContactSolverMethod::Pgs);
  EXPECT_EQ(soft.settings().solver, Settings::ContactSolverMethod::SoftStep);
  for (const World* w : {&pgs, &soft}) {
    const Settings& s = w->settings();
    EXPECT_DOUBLE_EQ(s.timeStep, 1.0 / 60.0);  // the issue's dt [s]
    EXPECT_FALSE(s.allowSleep);
    EXPECT_EQ(s.integrator, pgs.settings().integrator);
    EXPECT_EQ(s.gravity, pgs.settings().gravity);
    EXPECT_EQ(s.substeps, pgs.settings().substeps);
    EXPECT_EQ(s.velocityIterations, pgs.settings().velocityIterations);
  }
  constexpr std::size_t kBoxes = 20 + 20 * 21 / 2;  // column + pyramid rows 20, 19, ..., 1
  ASSERT_EQ(pgs.bodies().size(), kBoxes);
  ASSERT_EQ(soft.bodies().size(), kBoxes);
  for (std::size_t i = 0; i < kBoxes; ++i) {
    EXPECT_EQ(pgs.bodies()[i].name(), soft.bodies()[i].name());
    EXPECT_EQ(pgs.bodies()[i].mass(), soft.bodies()[i].mass());
  }
  EXPECT_EQ(pgs.stateHash(), soft.stateHash());  // the same state at t = 0
  EXPECT_EQ(phase.worlds[0].scene.stepCount(), phase.worlds[1].scene.stepCount());

  // A short run without rendering, as `rbsim run --no-render` does: both worlds step in
  // lockstep, every step of each is counted, and their traces carry "K/NAME".
  std::vector<Phase> phases = {loadPhase(assetDir() + "/scenes/contact_solvers.json", {"world.duration=0.25"})};
  RunOptions options;
  options.render = false;
  options.quiet = true;
  options.tracePath = (std::filesystem::temp_directory_path() / ("rbsim_compare_trace_" + std::to_string(::getpid()) + ".csv")).string();
  options.traceEvery = 15;
  const RunSummary summary = runPhases(phases, options, "");
  EXPECT_EQ(summary.steps, 2u * 15u);  // 0.25 s at 1/60 s, in each of the two worlds
  std::ifstream trace(options.tracePath);
  std::set<std::string> tops;  // "STEP BODY" of the column's top box, from the columns step,t,body,...
  for (std::string line; std::getline(trace, line);) {
    const std::size_t a = line.find(','), b = line.find(',', a + 1), c = line.find(',', b + 1);
    const std::string body = line.substr(b + 1, c - b - 1);
    if (body.size() > 9 && body.substr(body.size() - 9) == "/stack_19") tops.insert(line.substr(0, a) + " " + body);
  }
  EXPECT_EQ(tops, (std::set<std::string>{"0 0/stack_19", "0 1/stack_19", "15 0/stack_19", "15 1/stack_19"}));
  std::filesystem::remove(options.tracePath);

  for (int s = 0; s < 15; ++s) {
    pgs.step();
    soft.step();
  }
  EXPECT_NE(pgs.stateHash(), soft.stateHash());  // the solver is all that differs, and it shows
}

// What docs/scene-format.md ("Comparing settings side by side") says the phase shows, over its full 10 s at dt = 1/60 s: the soft-step column of 20
// stands, sagging by about the 7 mm engine/include/rbsim/settings/settings.h quotes for 8 substeps of 120 Hz
// contacts, while the PGS column (10 sweeps) buckles and falls. A solver change that alters
// either outcome fails here, so the demo's caption and that text get revisited with it.
TEST(ComparedPhase, TheSoftStepColumnStandsAndThePgsColumnFalls) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "a 10 s outcome; the sanitizers run this scene for 0.25 s above";
  const Phase phase = loadPhase(assetDir() + "/scenes/contact_solvers.json");
  World pgs = buildWorld(phase.worlds[0].scene), soft = buildWorld(phase.worlds[1].scene);
  const std::uint64_t steps = phase.scene().stepCount();
  ASSERT_EQ(steps, 600u);  // 10 s at 1/60 s
  for (std::uint64_t s = 0; s < steps; ++s) {
    pgs.step();
    soft.step();
  }
  constexpr std::size_t kTop = 19;            // stack_19, the column's top box
  constexpr double kColumnX = 12.5;           // [m] the column's x (make_contact_solvers.py)
  constexpr double kTopStartY = 19.5;         // [m] its centre's height at t = 0
  constexpr double kMaxSag = 0.02;            // [m] settings.h: 7 mm lost by 20 boxes
  constexpr double kMaxDrift = 0.05;          // [m] horizontal, a column still standing
  constexpr double kFallenBelow = 10.0;       // [m] the top box has come down half the column
  ASSERT_EQ(soft.bodies()[kTop].name(), "stack_19");
  const Vec3 top = soft.bodies()[kTop].position();
  EXPECT_GT(top.y(), kTopStartY - kMaxSag);
  EXPECT_LT(std::hypot(top.x() - kColumnX, top.z()), kMaxDrift);
  EXPECT_LT(pgs.bodies()[kTop].position().y(), kFallenBelow);
}

// One frame holds both worlds, each in a pane of its own (world k's bodies where world k has
// them, unmoved), one selected body (the panel follows the first world), and a caption per world
// at the top left of its pane, right of the panel's column.
TEST(ComparedPhase, OneFrameDrawsEveryWorldInItsPaneWithItsCaption) {
  const Phase phase = loadPhase(assetDir() + "/scenes/contact_solvers.json");
  std::vector<World> worlds;
  for (const PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
  worlds[1].step();  // so the panes cannot both be world 0's
  const render::FrameData frame = buildPhaseFrame(worlds, phase, "Demo 5");
  EXPECT_TRUE(frame.bodies.empty());
  ASSERT_EQ(frame.panes.size(), 2u);
  const std::size_t n = worlds[0].bodies().size();
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_EQ(frame.panes[k].bodies.size(), n);
    for (std::size_t i = 0; i < n; i += 23) {
      const Vec3 x = worlds[k].bodies()[i].position();
      EXPECT_FLOAT_EQ(frame.panes[k].bodies[i].position.y, static_cast<float>(x.y()));
    }
  }
  EXPECT_NE(frame.panes[0].bodies[n - 1].position.y, frame.panes[1].bodies[n - 1].position.y);
  int selected = 0;
  for (const render::FrameData& pane : frame.panes) {
    for (const render::BodyView& b : pane.bodies) selected += b.selected ? 1 : 0;
  }
  EXPECT_EQ(selected, 1);
  ASSERT_EQ(frame.overlay.labels.size(), 2u);
  EXPECT_EQ(frame.overlay.labels[0].text, "PGS");
  EXPECT_EQ(frame.overlay.labels[1].text, "soft step");
  const ViewDesc& view = phase.scene().view;
  EXPECT_TRUE(frame.infoColumn);
  EXPECT_TRUE(frame.overlay.plotsUnderPanel);
  const std::vector<render::PaneRect> rects = render::paneLayout(2, view.width, view.height, true, frame.overlay.panel);
  for (std::size_t k = 0; k < 2; ++k) {
    const render::OverlayLabel& label = frame.overlay.labels[k];
    EXPECT_TRUE(label.leftAligned);
    EXPECT_GT(label.pixel.x, static_cast<float>(rects[k].x));
    EXPECT_LT(label.pixel.x, static_cast<float>(rects[k].x + rects[k].width / 4));
    EXPECT_GT(label.pixel.y, static_cast<float>(rects[k].y));
    EXPECT_LT(label.pixel.y, static_cast<float>(rects[k].y + rects[k].height / 4));
    EXPECT_GE(static_cast<float>(rects[k].x), render::infoColumnWidth(view.width, view.height, frame.overlay.panel) - 1.0f);
  }
}

// The mechanism is not tied to one key: worlds of different dt step in lockstep by time, the
// caption defaults to "KEY = VALUE", and --set reaches the block itself but may not set the
// compared key.
TEST(ComparedPhase, AnyKeyWorksAndWorldsOfDifferentStepsKeepTheSameTime) {
  const std::string text = R"({"world": {"gravity": [0, -9.81, 0], "dt": 0.01, "duration": 0.1},
    "compare": {"key": "world.dt", "values": [0.01, 0.005]},
    "bodies": [{"name": "a", "shape": {"type": "box", "extents": [3, 1, 1]}, "mass": 1}]})";
  const Phase phase = parsePhaseText(text, "inline.json", ".");
  ASSERT_EQ(phase.worlds.size(), 2u);
  EXPECT_EQ(phase.worlds[0].label, "world.dt = 0.01");
  EXPECT_EQ(phase.worlds[1].label, "world.dt = 0.005");
  EXPECT_EQ(phase.worlds[0].scene.stepCount(), 10u);
  EXPECT_EQ(phase.worlds[1].scene.stepCount(), 20u);
  EXPECT_EQ(frameCount(phase), frameCount(phase.worlds[0].scene));

  RunOptions options;
  options.render = false;
  options.quiet = true;
  EXPECT_EQ(runPhases({phase}, options, "").steps, 10u + 20u);

  const Phase three = parsePhaseText(text, "inline.json", ".", {"compare.values=[0.01, 0.005, 0.0025]"});
  EXPECT_EQ(three.worlds.size(), 3u);
  EXPECT_DOUBLE_EQ(three.worlds[2].scene.settings.timeStep, 0.0025);
  EXPECT_THROW(parsePhaseText(text, "inline.json", ".", {"world.dt=0.02"}), InputError);
}


// The worlds of a comparison are described from one document and cooked through one cache
// (rbsim/scene/cook.h): a shape no compared value touches is read and built once for all.
TEST(ComparedPhase, EachDistinctShapeIsDescribedAndCookedOnceForEveryWorld) {
  const std::string text = R"({"world": {"dt": 0.01, "duration": 0.1},
    "compare": {"key": "world.integrator", "values": ["euler-quat", "dlm", "rk4", "symplectic-euler"]},
    "bodies": [{"name": "ring", "shape": {"type": "torus", "major_radius": 0.3, "minor_radius": 0.1}, "density": 100},
               {"name": "ring2", "shape": {"type": "torus", "major_radius": 0.3, "minor_radius": 0.1}, "density": 100,
                "position": [1, 0, 0]}]})";
  const Phase phase = parsePhaseText(text, "inline.json", ".");
  ASSERT_EQ(phase.worlds.size(), 4u);
  const BodyDef& first = phase.worlds[0].scene.bodies[0];
  ASSERT_NE(first.sdf, nullptr) << "a torus is closed and non-convex: it collides through a grid";
  for (const PhaseWorld& world : phase.worlds) {
    EXPECT_TRUE(world.scene.cooking.empty()) << world.label;
    for (const BodyDef& def : world.scene.bodies) {
      EXPECT_EQ(def.mesh.get(), first.mesh.get()) << world.label << ": " << def.name;
      EXPECT_EQ(def.sdf.get(), first.sdf.get()) << world.label << ": " << def.name;
      EXPECT_EQ(def.triangles.get(), first.triangles.get()) << world.label << ": " << def.name;
    }
  }
  EXPECT_NE(phase.worlds[1].scene.settings.integrator, phase.worlds[0].scene.settings.integrator);
}

// A world whose frames are drawn steps on one thread (the rasteriser and the encoder have the
// cores), unless the scene gives world.threads, in its file or by --set: then it keeps that.
TEST(FramedWorld, StepsOnOneThreadUnlessTheSceneGivesThreads) {
  const std::string text = R"({"world": {"dt": 0.01, "duration": 0.1},
    "bodies": [{"name": "a", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1}]})";
  const Scene plain = parsePhaseText(text, "inline.json", ".").worlds[0].scene;
  EXPECT_FALSE(plain.threadsGiven);
  EXPECT_EQ(buildWorld(plain).settings().threads, machineThreads());
  EXPECT_EQ(buildFramedWorld(plain).settings().threads, 1);

  const Scene set = parsePhaseText(text, "inline.json", ".", {"world.threads=3"}).worlds[0].scene;
  EXPECT_TRUE(set.threadsGiven);
  EXPECT_EQ(buildFramedWorld(set).settings().threads, 3);

  const std::string given = R"({"world": {"dt": 0.01, "duration": 0.1, "threads": 2},
    "bodies": [{"name": "a", "shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1}]})";
  EXPECT_EQ(buildFramedWorld(parsePhaseText(given, "inline.json", ".").worlds[0].scene).settings().threads, 2);
}

}  // namespace
}  // namespace rbsim::app
