// Frame output: the MP4 must be what ffprobe calls a 10-frame H.264 yuv420p video of the right
// size, PNGs must decode to exactly the submitted pixels, and failures must be clear errors.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <stb/stb_image.h>  // implementation is in Debian's libstb, linked via rbsim_render

#include "render/ffmpeg_log.h"
#include "render/frame_sink.h"
#include "render/offscreen_renderer.h"
#include "render/render_error.h"
#include "render_test_util.h"

namespace rbsim::render::test {
namespace {

constexpr int kFrameSinkWidth = 320;
constexpr int kFrameSinkHeight = 240;
constexpr int kFrames = 10;

bool onPath(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

std::string runCommand(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  pclose(pipe);
  while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
  return output;
}

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, had_ = true;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() { had_ ? setenv(name_, old_.c_str(), 1) : unsetenv(name_); }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

TEST(FrameSink, TenFramesBecomeAnH264VideoAndLosslessPngs) {
  if (!onPath("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  const auto video = dir.path() / "nested" / "folder" / "run.mp4";  // parents do not exist yet
  const auto pngs = dir.path() / "frames";
  OffscreenRenderer renderer(kFrameSinkWidth, kFrameSinkHeight, shaderDir());
  std::vector<std::uint8_t> firstImage;
  {
    FrameSink sink(SinkOptions{pngs, video, 30, kFrameSinkWidth, kFrameSinkHeight});
    FrameData frame;
    frame.options.overlay = false;
    for (int i = 0; i < kFrames; ++i) {
      frame.bodies = {makeBox({0.2f * i, 0.5f, 0.0f}, glm::vec3(0.5f), glm::mat3(1.0f),
                              {0.8f, 0.5f, 0.2f})};
      const std::vector<std::uint8_t>& image = renderer.render(frame);
      if (i == 0) firstImage = image;
      sink.submit(image);
    }
    sink.finish();
    EXPECT_EQ(sink.timing().frames, kFrames);
    EXPECT_GT(sink.timing().pngMs, 0.0);
    EXPECT_GT(sink.timing().videoMs, 0.0);
  }
  ASSERT_TRUE(std::filesystem::exists(video));

  for (int i = 0; i < kFrames; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", i);
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load((pngs / name).c_str(), &w, &h, &channels, 4);
    ASSERT_NE(pixels, nullptr) << name << ": " << stbi_failure_reason();
    EXPECT_EQ(w, kFrameSinkWidth);
    EXPECT_EQ(h, kFrameSinkHeight);
    if (i == 0) {
      // Lossless and opaque: the rendered colours, alpha 255 (PNG frames are RGB, png_file.h).
      EXPECT_EQ(channels, 3);
      std::size_t different = 0;
      for (std::size_t k = 0; k < firstImage.size(); ++k) {
        different += pixels[k] != (k % 4 == 3 ? 255 : firstImage[k]) ? 1 : 0;
      }
      EXPECT_EQ(different, 0u) << "PNG is lossless: frame 0 must decode to the rendered colours";
    }
    stbi_image_free(pixels);
  }
  EXPECT_FALSE(std::filesystem::exists(pngs / "frame_000010.png"));

  if (!onPath("ffprobe")) GTEST_SKIP() << "ffprobe is not installed; PNGs checked, video not";
  // ffprobe prints the entries in its own order: codec_name, width, height, pix_fmt, frames.
  const std::string probe = runCommand(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,nb_read_frames,width,height,pix_fmt -of csv=p=0 '" +
      video.string() + "'");
  EXPECT_EQ(probe, "h264,320,240,yuv420p,10");
}

TEST(FrameSink, MissingFfmpegIsAnErrorBeforeAnyFrame) {
  TempDir dir;
  ScopedEnv path("PATH", dir.path().string());  // an empty folder: no ffmpeg on PATH
  try {
    FrameSink sink(SinkOptions{std::nullopt, dir.path() / "out.mp4", 30, kFrameSinkWidth, kFrameSinkHeight});
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg"), std::string::npos) << e.what();
  }
}

TEST(FrameSink, UnwritableFolderIsAnErrorNamingThePath) {
  TempDir dir;
  const auto blocker = dir.path() / "a_file";
  std::ofstream(blocker) << "not a folder";
  const auto pngs = blocker / "frames";
  try {
    FrameSink sink(SinkOptions{pngs, std::nullopt, 30, kFrameSinkWidth, kFrameSinkHeight});
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find(pngs.string()), std::string::npos) << e.what();
  }
}

TEST(FrameSink, AVideoPathThatIsAFolderNamesItAndTheReason) {
  TempDir dir;
  try {
    FrameSink sink(SinkOptions{std::nullopt, dir.path(), 30, kFrameSinkWidth, kFrameSinkHeight});
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write video file " + dir.path().string() + ": Is a directory"),
              std::string::npos) << e.what();
  }
}

TEST(FrameSink, AFramesFolderThatIsAFileIsRefusedBeforeFfmpegStarts) {
  TempDir dir;
  const auto blocker = dir.path() / "a_file";
  std::ofstream(blocker) << "not a folder";
  try {
    FrameSink sink(SinkOptions{blocker, dir.path() / "out.mp4", 30, kFrameSinkWidth, kFrameSinkHeight});
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("a file that is not a folder is in the way"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.mp4"));  // the PNG folder is checked first
}

// ffmpeg's reason comes last: after 5000 lines of warnings the kept log still ends with it, and the
// message quotes the last 12 lines (a kept head of 64 KB lost it).
TEST(FfmpegLog, KeepsTheLastLinesWhereTheReasonIs) {
  std::string log;
  for (int i = 0; i < 5000; ++i) {
    const std::string line = "warning " + std::to_string(i) + ": past duration too large\n";
    appendFfmpegLog(log, line.data(), line.size());
  }
  const std::string reason = "out.mp4: No space left on device\n\n";
  appendFfmpegLog(log, reason.data(), reason.size());
  EXPECT_LE(log.size(), kFfmpegLogBytes);
  const std::string tail = ffmpegLogTail(log);
  EXPECT_EQ(std::count(tail.begin(), tail.end(), '\n'), kFfmpegLogLines - 1);
  EXPECT_EQ(tail.substr(tail.size() - 32), "out.mp4: No space left on device");
  EXPECT_EQ(tail.find("warning 4988"), std::string::npos);
  EXPECT_NE(tail.find("warning 4989"), std::string::npos);
  EXPECT_EQ(ffmpegLogTail("one line\n"), "one line");
  EXPECT_EQ(ffmpegLogTail(""), "");
}

TEST(FrameSink, FfmpegFailureIsReportedByFinish) {
  if (!onPath("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  TempDir dir;
  // No muxer is named by this extension, so ffmpeg exits with an error.
  FrameSink sink(SinkOptions{std::nullopt, dir.path() / "out.not_a_format", 30, 16, 16});
  try {
    for (int i = 0; i < 3; ++i) sink.submit(std::vector<std::uint8_t>(16 * 16 * 4, 128));
    sink.finish();
    FAIL() << "expected RenderError";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg"), std::string::npos) << e.what();
  }
}

TEST(FrameSink, WrongImageSizeIsRejected) {
  TempDir dir;
  FrameSink sink(SinkOptions{dir.path(), std::nullopt, 30, kFrameSinkWidth, kFrameSinkHeight});
  EXPECT_THROW(sink.submit(std::vector<std::uint8_t>(10)), RenderError);
}

}  // namespace
}  // namespace rbsim::render::test
