// --record and `rbsim replay` (app/record/recording.h): a replay draws the original's frames bit
// for bit without simulating, for bodies with forces, a compared phase with plots, particles,
// soft bodies, bodies that break or are spawned, and a 2D world (every shipped scene's trace:
// record_every_scene_test.cpp); a recording cut short, damaged, of another version or of other
// scenes is refused with a message, never misread.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "run/paths.h"
#include "rbsim/io/input_error.h"
#include "record/recording.h"
#include "run/phase.h"
#include "run/runner.h"

namespace rbsim::app {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rbsim_record_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> smallRun(const std::string& steps) {
  return {"world.steps=" + steps, "view.size=[160,90]", "view.fps=30"};
}

std::vector<Phase> phasesOf(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides) {
  std::vector<Phase> phases;
  for (const std::string& scene : scenes) phases.push_back(loadPhase(assetDir() + "/scenes/" + scene, overrides));
  return phases;
}

// Every frame of a run (no files but the recording): with `record`, into that file.
std::vector<std::vector<std::uint8_t>> frames(const std::vector<Phase>& phases, const std::string& record,
                                              RecordReader* replay, const fs::path& dir,
                                              const std::vector<std::string>& overrides = {}) {
  RunOptions options;
  options.quiet = true;
  options.overrides = overrides;  // what the phases were loaded with, for the recording's header
  options.recordPath = record;
  options.framesDir = (dir / (replay != nullptr ? "replayed" : "original")).string();
  std::vector<std::vector<std::uint8_t>> out;
  runPhases(phases, options, "record test", [&](const std::vector<std::uint8_t>& image) { out.push_back(image); }, replay);
  return out;
}

TEST(Record, AReplayDrawsTheOriginalFramesBitForBit) {
  const fs::path dir = tempDir("bits");
  // Forces at a point (their arrows), three integrators side by side with plots, particles, a soft
  // body; a wall that breaks within the 90 steps and ragdolls spawned (their meshes and colours
  // drawn from the bodies a snapshot made), a 2D world.
  const std::vector<std::vector<std::string>> runs = {
      {"assignment2_c_force_at_point.json", "assignment2_e_integrators.json"},
      {"particles_fountain.json"},
      {"soft_jelly.json"},
      {"fracture_wall.json", "machinery_rain.json"},
      {"planar_tumbling.json"}};
  for (const std::vector<std::string>& scenes : runs) {
    const std::vector<std::string> overrides = smallRun("90");
    const std::string file = (dir / "run.rbrec").string();
    const std::vector<std::vector<std::uint8_t>> original = frames(phasesOf(scenes, overrides), file, nullptr, dir, overrides);
    RecordReader reader(file);
    EXPECT_EQ(reader.header().overrides, overrides);
    EXPECT_EQ(reader.header().phases.size(), scenes.size());
    const std::vector<std::vector<std::uint8_t>> replayed = frames(phasesOf(scenes, overrides), "", &reader, dir);
    ASSERT_EQ(replayed.size(), original.size()) << scenes.front();
    for (std::size_t f = 0; f < original.size(); ++f) EXPECT_TRUE(replayed[f] == original[f]) << scenes.front() << " frame " << f;
  }
  fs::remove_all(dir);
}

// A replay at another frame rate visits a compared phase's worlds (of different dt) in another
// order than the recording run did: it still draws what a run at that rate draws.
TEST(Record, AReplayAtAnotherFrameRateIsThatRunBitForBit) {
  const fs::path dir = tempDir("fps");
  const std::vector<std::string> base = {"world.steps=120", "view.size=[160,90]",
                                         R"(compare={"key": "world.dt", "values": [0.01, 0.02, 0.0041666]})"};
  std::vector<std::string> at30 = base, at60 = base;
  at30.push_back("view.fps=30");
  at60.push_back("view.fps=60");
  const std::string file = (dir / "fps.rbrec").string();
  frames(phasesOf({"assignment2_b_velocity.json"}, at30), file, nullptr, dir, at30);
  const std::vector<std::vector<std::uint8_t>> direct = frames(phasesOf({"assignment2_b_velocity.json"}, at60), "", nullptr, dir);
  RecordReader reader(file);
  const std::vector<std::vector<std::uint8_t>> replayed = frames(phasesOf({"assignment2_b_velocity.json"}, at60), "", &reader, dir);
  ASSERT_EQ(replayed.size(), direct.size());
  for (std::size_t f = 0; f < direct.size(); ++f) EXPECT_TRUE(replayed[f] == direct[f]) << "frame " << f;
  fs::remove_all(dir);
}

std::string errorOf(const std::string& file, const std::vector<Phase>& phases, const fs::path& dir) {
  try {
    RecordReader reader(file);
    frames(phases, "", &reader, dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Record, ACutDamagedForeignOrOtherVersionRecordingIsRefused) {
  const fs::path dir = tempDir("bad");
  const std::vector<Phase> phases = phasesOf({"assignment2_b_velocity.json"}, smallRun("60"));
  const std::string good = (dir / "good.rbrec").string();
  frames(phases, good, nullptr, dir);
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  EXPECT_EQ(errorOf(good, phases, dir), "accepted");
  const auto variant = [&](const std::string& name, const std::string& content) {
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return errorOf(path, phases, dir);
  };
  // Cut anywhere: in the magic, the header, a block, before the end marker.
  for (const std::size_t keep : {std::size_t{3}, std::size_t{14}, std::size_t{200}, bytes.size() / 2, bytes.size() - 20,
                                 bytes.size() - 1}) {
    const std::string message = variant("cut.rbrec", bytes.substr(0, keep));
    EXPECT_NE(message, "accepted") << keep;
    EXPECT_TRUE(message.find("truncated") != std::string::npos || message.find("not an rbsim recording") != std::string::npos ||
                message.find("ends after") != std::string::npos || message.find("damaged") != std::string::npos)
        << keep << ": " << message;
  }
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x5a);
  EXPECT_NE(variant("flipped.rbrec", flipped).find("damaged"), std::string::npos);
  std::string version = bytes;
  version[8] = 7;  // the format version's low byte
  EXPECT_NE(variant("version.rbrec", version).find("format version 7"), std::string::npos);
  std::string rbsim = bytes;
  const std::size_t at = rbsim.find(std::string("\"rbsim\":\"") + RBSIM_VERSION);
  ASSERT_NE(at, std::string::npos);
  rbsim[at + 9] = '9';  // another rbsim's version, same length: the header's checksum catches the edit
  EXPECT_NE(variant("rbsim.rbrec", rbsim).find("does not match its checksum"), std::string::npos);
  EXPECT_NE(variant("scene.rbrec", "{\"bodies\": []}").find("not an rbsim recording"), std::string::npos);
  // Another scene: its entries do not fit.
  EXPECT_NE(errorOf(good, phasesOf({"contact_stacking.json"}, smallRun("60")), dir).find("does not belong"),
            std::string::npos);
  // More steps than the recording holds, and fewer.
  EXPECT_NE(errorOf(good, phasesOf({"assignment2_b_velocity.json"}, smallRun("90")), dir).find("ends after 60 steps"),
            std::string::npos);
  EXPECT_NE(errorOf(good, phasesOf({"assignment2_b_velocity.json"}, smallRun("30")), dir).find("holds more steps"),
            std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rbsim::app
