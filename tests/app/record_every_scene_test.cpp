// Every shipped scene (assets/scenes/*.json, which hold every demo's phases, and the Box3D
// scenes that spawn) records and replays bit for bit (issue 58): `rbsim run SCENE --record R --trace A` and `rbsim replay R
// --trace B` write the same trace, byte for byte, and the replayed World hashes as the run's at
// every step (World::stateHash: bodies, particles, soft-body nodes, 2D bodies). Scenes that
// spawn, remove (kill volume, lifetimes) and break bodies change their set of bodies in the steps
// run, which the recording carries as World snapshots (record/entry_codec.h).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "demos/demo.h"
#include "record/recording.h"
#include "render/body_colors.h"
#include "run/paths.h"
#include "run/phase.h"
#include "run/runner.h"
#include "rbsim/io/input_error.h"
#include "rbsim/world/systems.h"
#include "../sanitized_build.h"

namespace rbsim::app::every_scene {
namespace {

namespace fs = std::filesystem;

// Steps a scene is run for: short, as the test runs every scene; the scenes whose bodies change
// run until they have (the first fracture, a lifetime's removal; kChangingScenes). Under the
// sanitizers 12 (soft_bars' 24 soft steps took 20 s there; the normal build runs 24).
const int kSteps = test::kSanitizedBuild ? 12 : 24;

struct ChangingScene {
  const char* file;
  int steps;            // enough for every kind of change the scene makes
  std::uint64_t least;  // steps that changed the bodies, at least
};
// fracture_wall's first wall breaks by step 90 (dt 1/240 s); machinery_rain's first burst is at
// step 1 and its lifetime of 3 s removes it at step 181 (dt 1/60 s); rain's first columns fall
// at step 1; large_world's 100 spawners fire once, at step 6 (t = 1/12 s). Under the sanitizers
// machinery_rain's figures live 0.5 s (kSanitizedRainLifetime), so the same removal comes at
// step 31 of 40, after one burst: two changes (the normal build runs the scene as shipped: four
// bursts, the last with the first row's removal).
const ChangingScene kChangingScenes[] = {{"fracture_wall.json", 90, 1},
                                         {"machinery_rain.json", test::kSanitizedBuild ? 40 : 190, test::kSanitizedBuild ? 2u : 4u},
                                         {"box3d/rain.json", 6, 1},
                                         {"box3d/large_world.json", 7, 1}};
const std::vector<std::string> kSanitizedRainLifetime = {"spawn[0].lifetime=0.5"};
const std::vector<std::string> kNoOverrides;

// The overrides a scene is run with besides its step count.
const std::vector<std::string>& overridesOf(const std::string& file) {
  return test::kSanitizedBuild && file == "machinery_rain.json" ? kSanitizedRainLifetime : kNoOverrides;
}

// assets/scenes/*.json and the Box3D scenes that change their bodies (the other Box3D scenes
// are piles of thousands of bodies: 4 to 48 s each to build and step four times here, for no
// path of the recording that the scenes above do not take).
std::vector<std::string> shippedScenes() {
  std::vector<std::string> out;
  for (const fs::directory_entry& e : fs::directory_iterator(fs::path(assetDir()) / "scenes")) {
    if (e.path().extension() == ".json") out.push_back(e.path().filename().string());
  }
  out.push_back("box3d/rain.json");
  out.push_back("box3d/large_world.json");
  std::sort(out.begin(), out.end());
  return out;
}

int stepsOf(const std::string& file) {
  for (const ChangingScene& c : kChangingScenes) {
    if (file == c.file) return c.steps;
  }
  return kSteps;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

fs::path tempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rbsim_every_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<Phase> loadPhases(const std::vector<std::string>& files, const std::vector<std::string>& overrides) {
  std::vector<Phase> phases;
  for (const std::string& f : files) phases.push_back(loadPhase(assetDir() + "/scenes/" + f, overrides));
  return phases;
}

// `rbsim run` and `rbsim replay` in process: the run's trace against the replay's. The phases
// are the files loaded with the overrides (a scene is loaded once and used by every check: its
// shapes' meshing and grids are most of a short run's time under the sanitizers).
void runAndReplay(const std::vector<Phase>& phases, const std::vector<std::string>& files,
                  const std::vector<std::string>& overrides, const std::string& title, const fs::path& dir,
                  std::uint64_t leastChanges) {
  RunOptions run;
  run.quiet = true;
  run.render = false;
  run.overrides = overrides;
  run.recordPath = (dir / "run.rbrec").string();
  run.tracePath = (dir / "run.csv").string();
  const RunSummary recorded = runPhases(phases, run, title);
  EXPECT_GE(recorded.recordSnapshots, leastChanges) << files.front();

  RecordReader reader(run.recordPath);
  EXPECT_EQ(reader.header().title, title);
  std::vector<Phase> replayed;
  for (std::size_t i = 0; i < reader.header().phases.size(); ++i) {
    const RecordedPhase& p = reader.header().phases[i];
    reader.checkFiles(i);
    replayed.push_back(parsePhaseText(p.text, p.file, p.baseDir, reader.header().overrides));
  }
  RunOptions replay;
  replay.quiet = true;
  replay.render = false;
  replay.tracePath = (dir / "replay.csv").string();
  const RunSummary summary = runPhases(replayed, replay, title, {}, &reader);
  EXPECT_EQ(summary.steps, recorded.steps);
  const std::string original = readAll(run.tracePath), again = readAll(replay.tracePath);
  // More than the header: the bodies' rows (a 2D world alone has none: hashEveryStep sees it).
  if (!phases.front().scene().bodies.empty()) {
    EXPECT_GT(original.size(), 100u) << files.front();
  }
  EXPECT_TRUE(original == again) << files.front() << ": the replay's trace differs from the run's";
}

// FNV-1a over what the renderer draws with and stateHash leaves out: the bits of every body's R,
// and which earlier body's mesh object it shares (instanced bodies are drawn in batches by it).
std::uint64_t drawHash(const World& world) {
  constexpr std::uint64_t kPrime = 1099511628211ull, kBasis = 14695981039346656037ull;  // FNV-1a 64
  std::uint64_t h = kBasis;
  std::map<const Mesh*, std::uint64_t> first;
  for (const RigidBody& b : world.bodies()) {
    for (int k = 0; k < 9; ++k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, b.rotation().data() + k, sizeof bits);
      h = (h ^ bits) * kPrime;
    }
    h = (h ^ first.emplace(b.sharedMesh().get(), first.size()).first->second) * kPrime;
  }
  return h;
}

// Step by step: the replayed World's hash against the run's (the 2D bodies, particles and soft
// nodes are not in the trace), and its bodies' names and colours (what the renderer draws).
void hashEveryStep(const Phase& phase, const std::string& file, int steps, const fs::path& dir) {
  const std::string path = (dir / "hash.rbrec").string();
  std::vector<World> worlds;
  for (const PhaseWorld& w : phase.worlds) worlds.push_back(buildWorld(w.scene));
  std::vector<std::vector<std::uint64_t>> hashes(worlds.size());
  std::vector<std::vector<std::string>> last(worlds.size());  // names and colours at the end
  {
    RecordWriter writer(path, RecordingHeader{RBSIM_VERSION, "", {}, {{file, "", "{}", {}}}});
    for (int s = 0; s < steps; ++s) {
      for (std::size_t k = 0; k < worlds.size(); ++k) {
        worlds[k].step();
        writer.write(k, worlds[k]);
        hashes[k].push_back(worlds[k].stateHash() ^ drawHash(worlds[k]));
      }
    }
    writer.close();
  }
  // Colours are the app's, found by the body's name (app/render/body_colors.h).
  const auto looks = [](const World& w, const BodyColors& colors) {
    std::vector<std::string> out;
    for (const RigidBody& b : w.bodies()) {
      const Vec3 color = bodyColor(colors, b.name());
      out.push_back(b.name() + " " + std::to_string(color.x()) + " " + std::to_string(color.y()) + " " +
                    std::to_string(color.z()) + " " + std::to_string(b.mesh().vertices.size()));
    }
    return out;
  };
  for (std::size_t k = 0; k < worlds.size(); ++k) last[k] = looks(worlds[k], phase.worlds[k].scene.colors);
  RecordReader reader(path);
  std::vector<World> replayed;
  for (const PhaseWorld& w : phase.worlds) replayed.push_back(buildWorld(w.scene));
  for (int s = 0; s < steps; ++s) {
    for (std::size_t k = 0; k < replayed.size(); ++k) {
      reader.restoreNext(k, replayed.size(), replayed[k]);
      ASSERT_EQ(replayed[k].stateHash() ^ drawHash(replayed[k]), hashes[k][static_cast<std::size_t>(s)]) << file << " world " << k << " step " << s + 1;
    }
  }
  reader.expectEnd();
  for (std::size_t k = 0; k < replayed.size(); ++k) EXPECT_EQ(looks(replayed[k], phase.worlds[k].scene.colors), last[k]) << file;
}

class EveryScene : public testing::TestWithParam<std::string> {};

TEST_P(EveryScene, RecordsAndReplaysBitForBit) {
  const std::string file = GetParam();
  const int steps = stepsOf(file);
  std::uint64_t least = 0;
  for (const ChangingScene& c : kChangingScenes) {
    if (file == c.file) least = c.least;
  }
  const fs::path dir = tempDir(fs::path(file).stem().string());
  std::vector<std::string> overrides = {"world.steps=" + std::to_string(steps)};
  overrides.insert(overrides.end(), overridesOf(file).begin(), overridesOf(file).end());
  const std::vector<Phase> phases = loadPhases({file}, overrides);  // kept: scene() points into it
  runAndReplay(phases, {file}, overrides, "", dir, least);
  // What the trace does not show: step systems (particles, soft bodies, a 2D world) and the
  // bodies' looks after their set changed.
  const Scene& scene = phases.front().scene();
  if (least > 0 || scene.planar || !scene.particleSystems.empty() || !scene.softBodies.empty()) {
    hashEveryStep(phases.front(), file, steps, dir);
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryScene, testing::ValuesIn(shippedScenes()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.size() - 5);
                           std::replace(name.begin(), name.end(), '/', '_');
                           return name;
                         });

// The scenes the list above must hold: every demo's phases, and the kinds of change.
TEST(EveryScene, TheListHoldsEveryDemoPhaseAndEveryKindOfChange) {
  const std::vector<std::string> scenes = shippedScenes();
  const std::set<std::string> set(scenes.begin(), scenes.end());
  for (const Demo& demo : allDemos()) {
    for (const std::string& file : demo.scenes) EXPECT_EQ(set.count(file), 1u) << "demo " << demo.number << ": " << file;
  }
  for (const ChangingScene& c : kChangingScenes) EXPECT_EQ(set.count(c.file), 1u) << c.file;
  const Scene fracture = loadPhase(assetDir() + "/scenes/fracture_wall.json").scene();
  EXPECT_TRUE(std::any_of(fracture.bodies.begin(), fracture.bodies.end(), [](const BodyDef& b) { return b.fracture != nullptr; }));
  const Scene rain = loadPhase(assetDir() + "/scenes/machinery_rain.json").scene();
  EXPECT_FALSE(rain.spawners.empty());
  EXPECT_FALSE(rain.killVolume.empty());
  EXPECT_TRUE(loadPhase(assetDir() + "/scenes/planar_tumbling.json").scene().planar.has_value());
}

// A demo is recorded whole, as `rbsim demo 8 --record R` does: phases one after another, the
// last spawning and removing ragdolls; each phase's worlds start from their scene again.
TEST(EveryScene, AWholeDemoRecordsAndReplaysBitForBit) {
  const Demo* demo = findDemo(8);
  ASSERT_NE(demo, nullptr);
  const fs::path dir = tempDir("demo8");
  const std::vector<std::string> overrides = {"world.steps=70"};
  runAndReplay(loadPhases(demo->scenes, overrides), demo->scenes, overrides, "Demo 8: " + demo->name, dir, 1);
  fs::remove_all(dir);
}

// A scene whose bodies change and which has a system a World snapshot cannot hold is refused
// before the run, naming the file, the flag and both parts.
TEST(EveryScene, ChangingBodiesBesideParticlesAreRefusedBeforeTheRun) {
  const fs::path dir = tempDir("refused");
  const std::vector<Phase> phases = {
      loadPhase(assetDir() + "/scenes/particles_fountain.json", {R"(kill_volume={"min":[-9,-9,-9],"max":[9,9,9]})"})};
  RunOptions options;
  options.quiet = true;
  options.render = false;
  options.recordPath = (dir / "x.rbrec").string();
  try {
    runPhases(phases, options, "");
    ADD_FAILURE() << "recorded";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--record");
    EXPECT_NE(std::string(e.what()).find("particles_fountain.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("particles"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot be recorded"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(options.recordPath));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rbsim::app::every_scene
