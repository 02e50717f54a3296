// Outputs never touch inputs (run/output_paths.h, issue 37): the real rbsim, in a folder of the
// test's own, refuses every output that is an input (the scene by name, by hard link and by
// symlink; a mesh; the recording replayed) or another output, and every output that is a FIFO,
// and leaves the inputs byte for byte as they were. A FIFO given as a recording is refused, not
// opened (open() would block for ever). A --frames folder loses only an earlier run's frames.
// Empty flag values and window-only flags without --window are refused.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shell_command.h"

namespace {

namespace fs = std::filesystem;

constexpr const char* kScene =
    R"({"world": {"dt": 0.016666666666666666, "steps": 5}, "planes": [{"normal": [0, 1, 0]}],
        "bodies": [{"name": "box", "shape": {"type": "mesh", "file": "m.obj"}, "mass": 1, "position": [0, 1, 0]}]})";
constexpr const char* kCube =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\nv -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\n"
    "v 0.5 0.5 0.5\nv -0.5 0.5 0.5\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

class OutputPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rbsim_output_paths_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "s.json") << kScene;
    std::ofstream(dir_ / "m.obj") << kCube;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs rbsim in the test's folder under a 30 s timeout (a FIFO opened by mistake would block);
  // returns (exit code, stdout + stderr).
  std::pair<int, std::string> rbsim(const std::vector<std::string>& args) const {
    std::string command = "cd " + rbsim::test::shellQuote(dir_.string()) + " && timeout 30 " + rbsim::test::shellQuote(RBSIM_BINARY);
    for (const std::string& a : args) command += " " + rbsim::test::shellQuote(a);
    return rbsim::test::runCommand(command + " 2>&1");
  }
  // The run is refused (exit 2) with every fragment in its message, and the scene and the mesh are
  // as they were.
  void expectRefused(const std::vector<std::string>& args, const std::vector<std::string>& fragments) const {
    const auto [code, output] = rbsim(args);
    EXPECT_EQ(code, 2) << output;
    for (const std::string& f : fragments) EXPECT_NE(output.find(f), std::string::npos) << "no \"" << f << "\" in: " << output;
    EXPECT_EQ(contents(dir_ / "s.json"), kScene);
    EXPECT_EQ(contents(dir_ / "m.obj"), kCube);
  }

  fs::path dir_;
};

TEST_F(OutputPaths, AnOutputThatIsTheSceneOrAMeshIsRefused) {
  fs::create_hard_link(dir_ / "s.json", dir_ / "hard.json");
  fs::create_symlink("m.obj", dir_ / "link.obj");
  for (const char* flag : {"--trace", "--record"}) {
    expectRefused({"run", "s.json", "--no-render", flag, "s.json"}, {flag, "is the scene s.json being read"});
    expectRefused({"run", "s.json", "--no-render", flag, "./sub/../hard.json"}, {flag, "is the scene s.json"});
    expectRefused({"run", "s.json", "--no-render", flag, "link.obj"}, {flag, "is the mesh m.obj being read"});
  }
  expectRefused({"run", "s.json", "--size", "64x64", "--video", "m.obj"}, {"--video m.obj", "is the mesh"});
}

TEST_F(OutputPaths, TwoOutputsNamingOneFileAreRefused) {
  expectRefused({"run", "s.json", "--no-render", "--record", "r.bin", "--trace", "./r.bin"},
                {"--record r.bin", "is also --trace ./r.bin"});
  expectRefused({"run", "s.json", "--size", "64x64", "--record", "out.mp4", "--video", "out.mp4"}, {"is also --record out.mp4"});
  expectRefused({"run", "s.json", "--size", "64x64", "--trace", "out.mp4", "--video", "x/../out.mp4"}, {"is also --trace out.mp4"});
  EXPECT_FALSE(fs::exists(dir_ / "r.bin"));
  EXPECT_FALSE(fs::exists(dir_ / "out.mp4"));
}

TEST_F(OutputPaths, TheRecordingReplayedIsNeverWritten) {
  ASSERT_EQ(rbsim({"run", "s.json", "--no-render", "--record", "rec.bin"}).first, 0);
  const std::string recording = contents(dir_ / "rec.bin");
  expectRefused({"replay", "rec.bin", "--no-render", "--trace", "rec.bin"}, {"--trace rec.bin", "is the recording rec.bin"});
  expectRefused({"replay", "rec.bin", "--size", "64x64", "--video", "./rec.bin"}, {"is the recording rec.bin"});
  EXPECT_EQ(contents(dir_ / "rec.bin"), recording);
}

TEST_F(OutputPaths, FifosAreRefusedBeforeTheyAreOpened) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  expectRefused({"run", "s.json", "--no-render", "--trace", "pipe"}, {"--trace pipe", "is a FIFO"});
  expectRefused({"run", "s.json", "--no-render", "--record", "pipe"}, {"--record pipe", "is a FIFO"});
  expectRefused({"replay", "pipe", "--no-render"}, {"pipe", "is a FIFO", "expected a recording"});
  expectRefused({"run", "s.json", "--no-render", "--trace", "."}, {"--trace .", "is a folder"});
}

TEST_F(OutputPaths, AFramesFolderLosesOnlyAnEarlierRunsFrames) {
  fs::create_directories(dir_ / "frames");
  for (const char* name : {"frame_000007.png", "frame_1234567.png", "frame_12.png", "notes.txt", "frame_000001.jpg"}) {
    std::ofstream(dir_ / "frames" / name) << "old";
  }
  const auto [code, output] = rbsim({"run", "s.json", "--size", "64x64", "--frames", "frames", "--video", "v.mp4"});
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("removed 2 frames"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(dir_ / "frames" / "frame_000007.png"));
  EXPECT_FALSE(fs::exists(dir_ / "frames" / "frame_1234567.png"));
  for (const char* kept : {"frame_12.png", "notes.txt", "frame_000001.jpg"}) EXPECT_EQ(contents(dir_ / "frames" / kept), "old") << kept;
  EXPECT_TRUE(fs::exists(dir_ / "frames" / "frame_000000.png"));  // this run's first frame
  expectRefused({"run", "s.json", "--size", "64x64", "--frames", "m.obj"}, {"--frames m.obj", "is a file, not a folder"});
}

TEST_F(OutputPaths, EmptyValuesAndWindowFlagsWithoutAWindowAreRefused) {
  for (const char* flag : {"--gl", "--trace-every", "--png-level", "--window-frames", "--screenshot", "--trace", "--record"}) {
    const auto [code, output] = rbsim({"run", "s.json", flag, ""});
    EXPECT_EQ(code, 2) << flag << ": " << output;
    EXPECT_NE(output.find(flag), std::string::npos) << output;
  }
  expectRefused({"run", "s.json", "--no-render", "--window-frames", "3"}, {"--window-frames without --window", "add --window"});
  expectRefused({"run", "s.json", "--no-render", "--screenshot", "a.png"}, {"--screenshot without --window"});
  ASSERT_EQ(rbsim({"run", "s.json", "--no-render", "--record", "rec.bin"}).first, 0);
  expectRefused({"replay", "rec.bin", "--no-render", "--window-frames", "3"}, {"--window-frames without --window"});
}

}  // namespace
