// Outputs and numbers of a run: the trace is RFC 4180 CSV whatever the body names, every failed
// write (a full disk, a folder, a missing or read-only place) stops the run naming the file and
// the OS's reason, flags say their range in words, frame counts are computed without loops or
// overflow, and budgets refuse absurd runs with the estimate and the limit.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <stb/stb_image.h>  // the decoder, from Debian's libstb

#include "shell_command.h"

#include "cli/flag_values.h"
#include "rbsim/io/input_error.h"
#include "render/checked_file.h"
#include "render/frame_sink.h"
#include "render/png_file.h"
#include "render/render_error.h"
#include "run/output_budget.h"
#include "run/phase.h"
#include "run/runner.h"
#include "run/trace_writer.h"

namespace rbsim::app {
namespace {

namespace fs = std::filesystem;

// Runs the real rbsim; returns (exit code, stdout + stderr).
std::pair<int, std::string> runRbsim(const std::vector<std::string>& args, const std::string& redirect = "2>&1") {
  std::string command = test::shellQuote(RBSIM_BINARY);
  for (const std::string& a : args) command += " " + test::shellQuote(a);
  command += " " + redirect;
  return test::runCommand(command);
}

// A tiny RFC 4180 reader: records of fields, quoted fields may hold commas, "" and line breaks.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      EXPECT_TRUE(field.empty()) << "a quote inside an unquoted field at byte " << i;
      quoted = true;
    } else if (c == ',') {
      record.push_back(field);
      field.clear();
    } else if (c == '\n') {
      record.push_back(field);
      field.clear();
      records.push_back(record);
      record.clear();
    } else {
      field += c;
    }
  }
  EXPECT_FALSE(quoted) << "unterminated quoted field";
  EXPECT_TRUE(record.empty() && field.empty()) << "last record without a line break";
  return records;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rbsim_output_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(CsvField, QuotesOnlyWhatRfc4180Requires) {
  EXPECT_EQ(csvField("box"), "box");
  EXPECT_EQ(csvField("1/box"), "1/box");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csvField("cr\r"), "\"cr\r\"");
}

TEST(TraceCsv, BodyNamesWithCommasQuotesAndLineBreaksReadBackAsOneColumn) {
  const fs::path dir = freshDir("names");
  const std::vector<std::string> names = {"plain", "a,b", "say \"hi\"", "two\nlines", "\",\"\n"};
  std::string bodies;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::string json;  // the name as a JSON string
    for (char c : names[i]) json += c == '"' ? "\\\"" : c == '\n' ? "\\n" : std::string(1, c);
    bodies += std::string(i ? "," : "") + "{\"name\": \"" + json + "\", \"position\": [" + std::to_string(2 * i) +
              ",0,0], \"shape\": {\"type\": \"box\", \"extents\": [1,1,1]}, \"mass\": 1}";
  }
  std::ofstream(dir / "scene.json") << "{\"world\": {\"gravity\": [0,0,0], \"dt\": 0.01, \"steps\": 3}, \"bodies\": ["
                                    << bodies << "]}";
  const auto [code, output] = runRbsim({"run", (dir / "scene.json").string(), "--no-render", "--quiet", "--trace",
                                        (dir / "trace.csv").string()});
  ASSERT_EQ(code, 0) << output;
  std::stringstream text;
  text << std::ifstream(dir / "trace.csv", std::ios::binary).rdbuf();
  const auto records = parseCsv(text.str());
  ASSERT_EQ(records.size(), 1 + 4 * names.size());  // the header, then steps 0..3 for every body
  for (const auto& record : records) ASSERT_EQ(record.size(), 20u) << record.front();
  EXPECT_EQ(records[0][2], "body");
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(records[1 + i][0], "0");
    EXPECT_EQ(records[1 + i][2], names[i]);
    EXPECT_EQ(std::stod(records[1 + i][3]), 2.0 * static_cast<double>(i));  // x: the columns did not shift
  }
  fs::remove_all(dir);
}

TEST(CheckedFile, AFullDiskFailsWithTheOsReason) {
  render::CheckedFile file;
  ASSERT_TRUE(file.open("/dev/full"));
  const std::string row(100, 'x');
  file.write(row);  // buffered: may succeed here and fail at close
  EXPECT_FALSE(file.close());
  EXPECT_EQ(file.error(), "No space left on device");
}

std::string fileText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Issue 56: an output appears whole or not at all, and a file there before stays until it does.
TEST(CheckedFile, AnOutputAppearsWholeOrNotAtAll) {
  const fs::path dir = freshDir("atomic");
  const fs::path path = dir / "out.txt", partial = dir / "out.txt.partial";
  {
    render::CheckedFile file;
    ASSERT_TRUE(file.open(path));
    ASSERT_TRUE(file.write("first"));
    EXPECT_FALSE(fs::exists(path)) << "visible before it is whole";
    ASSERT_TRUE(file.close());
  }
  EXPECT_EQ(fileText(path), "first");
  EXPECT_FALSE(fs::exists(partial));
  {
    render::CheckedFile file;  // abandoned half-way, as by an exception: the old file stays
    ASSERT_TRUE(file.open(path));
    ASSERT_TRUE(file.write("sec"));
    EXPECT_EQ(fileText(path), "first");
  }
  EXPECT_EQ(fileText(path), "first");
  EXPECT_FALSE(fs::exists(partial));
  {
    render::CheckedFile file;
    ASSERT_TRUE(file.open(path));
    ASSERT_TRUE(file.write("second"));
    ASSERT_TRUE(file.close());
  }
  EXPECT_EQ(fileText(path), "second");
  EXPECT_FALSE(fs::exists(partial));
  fs::remove_all(dir);
}

// A run that fails (here it diverges at its first step) leaves the trace and the glTF export of
// the run before as they were: --gltf truncated its file before the run.
TEST(CheckedFile, AFailedRunKeepsTheOutputsOfTheRunBefore) {
  const fs::path dir = freshDir("failed_run");
  const fs::path gltf = dir / "run.glb", trace = dir / "trace.csv";
  const std::vector<std::string> scene{"run", std::string(RBSIM_BAD_DATA_DIR) + "/valid.json", "--no-render",
                                       "--gltf", gltf.string(), "--trace", trace.string()};
  const auto [good, goodOutput] = runRbsim(scene);
  ASSERT_EQ(good, 0) << goodOutput;
  const std::string gltfBefore = fileText(gltf), traceBefore = fileText(trace);
  ASSERT_GT(gltfBefore.size(), 100u);
  ASSERT_GT(traceBefore.size(), 100u);
  std::vector<std::string> diverging = scene;
  for (const char* set : {"bodies[0].mass=1e-10", "bodies[0].forces=[{\"force\":[1e308,0,0],\"start\":0,\"end\":1}]"}) {
    diverging.push_back("--set");
    diverging.push_back(set);
  }
  const auto [bad, badOutput] = runRbsim(diverging);
  EXPECT_EQ(bad, 2) << badOutput;
  EXPECT_NE(badOutput.find("diverged"), std::string::npos) << badOutput;
  EXPECT_EQ(fileText(gltf), gltfBefore);
  EXPECT_EQ(fileText(trace), traceBefore);
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().extension(), entry.path() == gltf ? ".glb" : ".csv") << entry.path() << " left behind";
  }
  fs::remove_all(dir);
}

TEST(CheckedFile, AFailedRunKeepsTheVideoAndTheRecordingOfTheRunBefore) {
  // Issue 56, item 7: ffmpeg wrote the video in place and the recording was truncated at its
  // start, so a run failing halfway left half a video and a recording with no end.
  const fs::path dir = freshDir("failed_video");
  const fs::path video = dir / "run.mp4", recording = dir / "run.rbrec";
  const std::vector<std::string> scene{"run", std::string(RBSIM_BAD_DATA_DIR) + "/valid.json", "--size", "64x64",
                                       "--video", video.string(), "--record", recording.string(), "--quiet"};
  const auto [good, goodOutput] = runRbsim(scene);
  ASSERT_EQ(good, 0) << goodOutput;
  const std::string videoBefore = fileText(video), recordingBefore = fileText(recording);
  ASSERT_GT(videoBefore.size(), 100u);
  ASSERT_GT(recordingBefore.size(), 100u);
  std::vector<std::string> diverging = scene;
  // Halfway (t = 0.05 s of 0.1 s), after frames have gone to ffmpeg and steps to the recording.
  for (const char* set : {"bodies[0].mass=1e-10", "bodies[0].forces=[{\"force\":[1e308,0,0],\"start\":0.05,\"end\":1}]"}) {
    diverging.push_back("--set");
    diverging.push_back(set);
  }
  const auto [bad, badOutput] = runRbsim(diverging);
  EXPECT_EQ(bad, 2) << badOutput;
  EXPECT_NE(badOutput.find("diverged"), std::string::npos) << badOutput;
  EXPECT_EQ(fileText(video), videoBefore);
  EXPECT_EQ(fileText(recording), recordingBefore);
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_TRUE(entry.path() == video || entry.path() == recording) << entry.path() << " left behind";
  }
  fs::remove_all(dir);
}

TEST(TraceWriter, AFullDiskStopsTheRunNamingTheFile) {
  try {
    TraceWriter trace("/dev/full");
    trace.close();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/dev/full");
    EXPECT_EQ(e.field(), "--trace");
    EXPECT_NE(e.problem().find("No space left on device"), std::string::npos) << e.what();
  }
}

TEST(PngFile, AFullDiskNamesThePathAndTheReason) {
  const std::vector<std::uint8_t> rgba(16 * 16 * 4, 128);
  try {
    render::encodePngFile("/dev/full", 16, 16, rgba.data(), render::kDefaultPngLevel);
    FAIL() << "no error";
  } catch (const render::RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("could not write PNG /dev/full: No space left on device"), std::string::npos)
        << e.what();
  }
  const fs::path dir = freshDir("png_folder");
  try {
    render::encodePngFile(dir, 16, 16, rgba.data(), render::kDefaultPngLevel);
    FAIL() << "no error";
  } catch (const render::RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("Is a directory"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// An image with what rendered frames have (flat areas, a gradient, sharp edges) and noise, at an
// odd size so no row is a multiple of anything.
std::vector<std::uint8_t> testImage(int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  std::mt19937 random(22);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      p[0] = static_cast<std::uint8_t>(x < width / 2 ? 200 : (255 * y) / height);
      p[1] = static_cast<std::uint8_t>(x % 7 == 0 ? 0 : 128);
      p[2] = static_cast<std::uint8_t>(y > height / 2 ? random() : 40);
      p[3] = static_cast<std::uint8_t>(x + y < width ? 255 : random());
    }
  }
  return rgba;
}

// The PNG holds the image's colours, opaque: RGB, three channels, whatever the alpha bytes were.
bool decodesTo(const fs::path& file, const std::vector<std::uint8_t>& rgba, int width, int height) {
  int w = 0, h = 0, channels = 0;
  unsigned char* back = stbi_load(file.string().c_str(), &w, &h, &channels, 4);
  bool same = back != nullptr && w == width && h == height && channels == 3;
  for (std::size_t i = 0; same && i < rgba.size(); ++i) same = back[i] == (i % 4 == 3 ? 255 : rgba[i]);
  stbi_image_free(back);
  return same;
}

// stb_image_write with libdeflate: every level and every row filter gives back the exact pixels.
TEST(PngFile, DecodesToTheExactPixelsAtEveryLevelAndRowFilter) {
  const int width = 97, height = 53;
  const std::vector<std::uint8_t> rgba = testImage(width, height);
  const fs::path dir = freshDir("png_exact");
  for (int filter = render::kMinPngRowFilter; filter <= render::kMaxPngRowFilter; ++filter) {
    render::setPngRowFilter(filter);
    for (int level = render::kMinPngLevel; level <= render::kMaxPngLevel; ++level) {
      const fs::path file = dir / ("f" + std::to_string(filter) + "_l" + std::to_string(level) + ".png");
      render::encodePngFile(file, width, height, rgba.data(), level);
      EXPECT_TRUE(decodesTo(file, rgba, width, height)) << "filter " << filter << " level " << level;
    }
  }
  render::setPngRowFilter(render::kDefaultPngRowFilter);
  EXPECT_THROW(render::setPngRowFilter(5), std::invalid_argument);
  EXPECT_THROW(render::encodePngFile(dir / "x.png", width, height, rgba.data(), 10), std::invalid_argument);
  // Levels above 0 compress, level 0 stores. (Level 9 against level 1 is not a rule: on this
  // small noisy image level 9 came out 22 bytes larger.)
  EXPECT_LT(fs::file_size(dir / "f0_l1.png"), fs::file_size(dir / "f0_l0.png") / 2);
  EXPECT_LT(fs::file_size(dir / "f0_l9.png"), fs::file_size(dir / "f0_l0.png") / 2);
  EXPECT_GT(fs::file_size(dir / "f0_l0.png"), rgba.size() / 4 * 3);  // RGB, stored
  fs::remove_all(dir);
}

// The frame writers run on several threads, each with its own level: their files stay exact.
TEST(PngFile, ThreadsWritingAtTheirOwnLevelsEachGetTheirOwn) {
  const int width = 64, height = 48;
  const std::vector<std::uint8_t> rgba = testImage(width, height);
  const fs::path dir = freshDir("png_threads");
  std::vector<std::thread> writers;
  for (int level : {0, 1, 6, 9}) {
    writers.emplace_back([&, level] {
      for (int k = 0; k < 20; ++k) {
        render::encodePngFile(dir / ("l" + std::to_string(level) + "_" + std::to_string(k) + ".png"), width, height, rgba.data(), level);
      }
    });
  }
  for (std::thread& t : writers) t.join();
  for (int level : {0, 1, 6, 9}) {
    for (int k = 0; k < 20; ++k) {
      EXPECT_TRUE(decodesTo(dir / ("l" + std::to_string(level) + "_" + std::to_string(k) + ".png"), rgba, width, height));
    }
    EXPECT_EQ(fs::file_size(dir / ("l" + std::to_string(level) + "_0.png")), fs::file_size(dir / ("l" + std::to_string(level) + "_19.png")));
  }
  EXPECT_GT(fs::file_size(dir / "l0_0.png"), fs::file_size(dir / "l9_0.png"));
  fs::remove_all(dir);
}

TEST(Stdout, ASummaryThatCannotBeWrittenIsAnError) {
  const auto [code, output] = runRbsim({"run", std::string(RBSIM_BAD_DATA_DIR) + "/valid.json", "--no-render"},
                                       "2>&1 >/dev/full");
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find("standard output: cannot write the summary (No space left on device)"), std::string::npos)
      << output;
}

// Issue 56: `rbsim --version > /dev/full` exited 0.
TEST(Stdout, VersionAndHelpThatCannotBeWrittenAreErrors) {
  for (const char* flag : {"--version", "--help"}) {
    const auto [code, output] = runRbsim({flag}, "2>&1 >/dev/full");
    EXPECT_EQ(code, 2) << flag << ": " << output;
    // The reason is the OS's when the last flush fails, "write error" when CLI11's own flush
    // already failed and stdio kept only the error flag.
    EXPECT_NE(output.find("standard output: cannot write the version or help text ("), std::string::npos) << output;
  }
  const auto [code, output] = runRbsim({"--version"}, "2>&1");
  EXPECT_EQ(code, 0) << output;
  EXPECT_NE(output.find("rbsim"), std::string::npos) << output;
}

TEST(FlagInteger, SaysTheRangeInWordsAndNeverWraps) {
  const auto message = [](const std::string& text) {
    try {
      parseFlagInteger("--window-frames", text, 1, 1000, "a frame count");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(parseFlagInteger("--x", "1000", 1, 1000, ""), 1000u);
  EXPECT_EQ(message("0"), "command line: --window-frames: expected a frame count; got 0, not in range 1 to 1000");
  EXPECT_NE(message("-1").find("got -1 (negative)"), std::string::npos);
  EXPECT_NE(message("99999999999999999999").find("got 99999999999999999999 (more than 64 bits hold)"), std::string::npos);
  EXPECT_NE(message("18446744073709551615").find("got 18446744073709551615, not in range"), std::string::npos);
  EXPECT_NE(message("2.5").find("got \"2.5\", not a whole number"), std::string::npos);
  EXPECT_NE(message("").find("not a whole number"), std::string::npos);
  EXPECT_EQ(parseImageSize("--size", "640x360"), std::make_pair(std::uint64_t{640}, std::uint64_t{360}));
  EXPECT_THROW(parseImageSize("--size", "99999999999999999999x2"), InputError);
  EXPECT_THROW(parseImageSize("--size", "-2x2"), InputError);
}

// --compare KEY=V1,V2 is the scene's compare block: values read as --set reads them (JSON if it
// parses, else a string), split at commas outside brackets and quotes.
TEST(Flags, CompareFlagIsACompareBlock) {
  EXPECT_EQ(nlohmann::json::parse(parseCompareFlag("world.integrator=euler-quat,dlm")),
            nlohmann::json::parse(R"({"key": "world.integrator", "values": ["euler-quat", "dlm"]})"));
  EXPECT_EQ(nlohmann::json::parse(parseCompareFlag(R"(bodies.box.position=[0,1,0],[0,2,0],"a,b",3)")),
            nlohmann::json::parse(R"({"key": "bodies.box.position", "values": [[0,1,0], [0,2,0], "a,b", 3]})"));
  for (const char* bad : {"world.solver", "=pgs,soft-step", "world.solver=pgs,", "world.solver=,pgs"}) {
    try {
      parseCompareFlag(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), std::string("--compare ") + bad);
    }
  }
  // The block the flag makes gives the worlds a file's block would.
  const Phase phase = loadPhase(std::string(RBSIM_BAD_DATA_DIR) + "/valid.json",
                                {"compare=" + parseCompareFlag("world.integrator=euler-quat,dlm")});
  ASSERT_EQ(phase.worlds.size(), 2u);
  EXPECT_EQ(phase.worlds[0].scene.settings.integrator, Integrator::EulerQuat);
  EXPECT_EQ(phase.worlds[1].scene.settings.integrator, Integrator::Dlm);
  EXPECT_EQ(phase.worlds[1].label, "world.integrator = dlm");
}

// The direct frame count against counting frame by frame, the definition.
TEST(FrameCount, MatchesCountingFrameByFrame) {
  for (const double fps : {1.0, 24.0, 60.0, 240.0}) {
    for (const double dt : {1e-4, 1.0 / 240.0, 0.007, 1.0 / 60.0, 0.05, 0.1}) {
      for (const std::uint64_t steps : {1u, 2u, 3u, 7u, 100u, 1001u}) {
        std::uint64_t counted = 0;
        while (stepOfFrame(counted, fps, dt) <= steps) ++counted;
        ASSERT_EQ(frameCount(steps, fps, dt), counted) << fps << " fps, dt " << dt << ", " << steps << " steps";
      }
    }
  }
}

TEST(FrameCount, ABillionStepsNeitherLoopsNorOverflows) {
  // 1e9 steps of 0.1 s shown at 240 fps: 2.4e10 frames, counted at once.
  EXPECT_EQ(frameCount(1'000'000'000, 240.0, 0.1), 24'000'000'012ull);  // k / 24 < 1e9 + 1/2
  EXPECT_EQ(frameCount(kHugeCount, 240.0, 0.1), kHugeCount);
  EXPECT_EQ(stepOfFrame(kHugeCount, 1.0, 1e-9), kHugeCount);  // saturates instead of wrapping
}

TEST(OutputBudget, RefusesAbsurdRunsWithTheEstimateAndTheLimit) {
  EXPECT_NO_THROW(checkOutputBudget("s.json", "x", kMaxRenderedFrames, 1280, 720, 60, "", 1));
  EXPECT_NO_THROW(checkOutputBudget("s.json", "x", 100'000, 1280, 720, 60, "frames", 1));  // ~45 GB
  try {
    checkOutputBudget("s.json", "1e+06 s at view.fps 60", 60'000'001, 1280, 720, 60, "", 1);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "world.duration");
    EXPECT_NE(e.problem().find("renders 60000001 frames (278 h of video at 60 fps); the limit is 1000000 frames"),
              std::string::npos) << e.what();
  }
  try {
    checkOutputBudget("s.json", "x", 1000, 8192, 8192, 60, "out", 0);  // 1000 x 268 MB stored
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--frames");
    EXPECT_NE(e.problem().find("need ~268 GB (~4 bytes a pixel); the limit is 100 GB"), std::string::npos) << e.what();
  }
}

TEST(OutputBudget, RefusesATraceOfAbsurdSize) {
  EXPECT_NO_THROW(checkTraceBudget("t.csv", 1e9, "x"));  // 100 GB at 100 bytes a row: the limit
  try {
    checkTraceBudget("t.csv", 2e9, "2000000000 steps in all, 1 bodies, --trace-every 1");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--trace");
    EXPECT_NE(e.problem().find("2e+09 rows (2000000000 steps in all, 1 bodies, --trace-every 1) need at least ~200 GB"),
              std::string::npos) << e.what();
  }
}

// Without images the runner jumps from one frame where a world steps to the next instead of
// visiting every frame; the trace (rows and their order across compared worlds of different dt)
// must be the one a rendered run writes.
TEST(NoRender, TracesTheSameRowsInTheSameOrderAsARenderedRun) {
  const fs::path dir = freshDir("lockstep");
  const std::string scene = std::string(RBSIM_BAD_DATA_DIR) + "/valid.json";
  const std::vector<std::string> common = {
      "run", scene, "--quiet", "--fps", "240", "--set", "world.gravity=[0,-9.8,0]",
      "--set", "compare={\"key\":\"world.dt\",\"values\":[0.01,0.003,0.02]}"};
  std::vector<std::string> rendered = common, simulated = common;
  rendered.insert(rendered.end(), {"--size", "64x64", "--video", (dir / "c.mp4").string(), "--trace",
                                   (dir / "rendered.csv").string()});
  simulated.insert(simulated.end(), {"--no-render", "--trace", (dir / "simulated.csv").string()});
  ASSERT_EQ(runRbsim(rendered).first, 0);
  ASSERT_EQ(runRbsim(simulated).first, 0);
  std::stringstream a, b;
  a << std::ifstream(dir / "rendered.csv").rdbuf();
  b << std::ifstream(dir / "simulated.csv").rdbuf();
  EXPECT_EQ(parseCsv(a.str()).size(), 1u + 11 + 34 + 6);  // header, then steps 0..10, 0..33, 0..5
  EXPECT_EQ(a.str(), b.str());
  fs::remove_all(dir);
}

TEST(FrameSink, QueuesOfHugeImagesAreShortened) {
  EXPECT_EQ(render::queueFramesWithin(8, 1280, 720), 8u);
  EXPECT_EQ(render::queueFramesWithin(8, 8192, 8192), 1u);
  EXPECT_EQ(render::queueFramesWithin(8, 2048, 2048), 3u);  // 3 x 16.8 MB within 66 MB
}

}  // namespace
}  // namespace rbsim::app
