// `rbsim demo all`: the frame plan (title cards + every demo's frames) is what a short run of the
// reel really writes, frames keep time at 60 fps whatever the time step, the reel's chapters
// (chapters.txt in YouTube's format, and in the MP4) follow the plan, and the progress line's
// clock and ETA read right.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demos/demo.h"
#include "run/progress.h"
#include "run/reel.h"
#include "run/runner.h"
#include "shell_command.h"
#include "../sanitized_build.h"

namespace rbsim::app {
namespace {

struct TextChapter {
  long long second = 0;
  std::string title;
};

// chapters.txt read as YouTube reads chapters from a description, written here apart from the
// code under test: each line "M:SS Title" or "H:MM:SS Title" (minutes and seconds two digits
// after a colon). A line that does not parse is a test failure.
std::vector<TextChapter> parseYoutubeChapters(const std::string& text) {
  static const std::regex line(R"(^(?:(\d+):([0-5]\d):([0-5]\d)|(\d+):([0-5]\d)) (\S.*)$)");
  std::vector<TextChapter> out;
  std::istringstream in(text);
  std::string row;
  while (std::getline(in, row)) {
    std::smatch m;
    if (!std::regex_match(row, m, line)) {
      ADD_FAILURE() << "not a YouTube chapter line: \"" << row << "\"";
      continue;
    }
    const long long seconds = m[1].matched ? std::stoll(m[1]) * 3600 + std::stoll(m[2]) * 60 + std::stoll(m[3])
                                           : std::stoll(m[4]) * 60 + std::stoll(m[5]);
    if (m[1].matched) {
      EXPECT_GE(seconds, 3600) << "H:MM:SS before an hour: " << row;
    }
    out.push_back({seconds, m[6]});
  }
  return out;
}

// YouTube's rules for chapters (YouTube Help, "Video chapters"): at least three, the first at
// 0:00, in increasing order, each at least 10 s long (the last up to the video's end).
void expectYoutubeRules(const std::vector<TextChapter>& chapters, double videoSeconds) {
  ASSERT_GE(chapters.size(), 3u);
  EXPECT_EQ(chapters.front().second, 0);
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    const double end = i + 1 < chapters.size() ? static_cast<double>(chapters[i + 1].second) : videoSeconds;
    EXPECT_GE(end - static_cast<double>(chapters[i].second), 10.0) << chapters[i].title;
  }
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Where each phase starts in the reel, counted here from the plan's frame counts: the opening
// card, then each demo's card and its phases (the first phase's chapter opens with its card, the
// very first with the opening card too).
std::vector<std::uint64_t> phaseStartFrames(const ReelPlan& plan) {
  std::vector<std::uint64_t> starts;
  std::uint64_t frame = plan.cardFrames;
  for (std::size_t i = 0; i < plan.demos.size(); ++i) {
    starts.push_back(i == 0 ? 0 : frame);
    frame += plan.cardFrames;
    for (std::size_t p = 0; p < plan.demos[i].phases.size(); ++p) {
      if (p > 0) starts.push_back(frame);
      frame += frameCount(plan.demos[i].phases[p]);
    }
  }
  EXPECT_EQ(frame, plan.totalFrames);
  return starts;
}

// The real reel's plan (nothing rendered): its chapters.txt meets YouTube's rules, and each
// chapter starts where a demo's card or a phase starts, at the first whole second from there.
TEST(ReelChapters, TheRealReelsChaptersMeetYouTubesRules) {
  const ReelOptions options;
  const ReelPlan plan = planReel(allDemos(), options);
  const std::vector<ReelChapter> chapters = reelChapters(plan, options);
  const std::vector<TextChapter> text = parseYoutubeChapters(youtubeChapters(chapters));
  ASSERT_EQ(text.size(), chapters.size());
  expectYoutubeRules(text, static_cast<double>(plan.totalFrames) / options.fps);
  const std::vector<std::uint64_t> starts = phaseStartFrames(plan);
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    EXPECT_NE(std::find(starts.begin(), starts.end(), chapters[i].startFrame), starts.end()) << chapters[i].title;
    const double start = static_cast<double>(chapters[i].startFrame) / options.fps;
    EXPECT_GE(static_cast<double>(text[i].second), start) << chapters[i].title;
    EXPECT_LT(static_cast<double>(text[i].second), start + 1.0) << chapters[i].title;
    EXPECT_EQ(text[i].title, chapters[i].title);
    EXPECT_EQ(chapters[i].endFrame, i + 1 < chapters.size() ? chapters[i + 1].startFrame : plan.totalFrames);
  }
  // Every demo is in a chapter's title.
  std::string titles;
  for (const ReelChapter& c : chapters) titles += c.title + "\n";
  for (const ReelDemo& d : plan.demos) {
    EXPECT_NE(titles.find("Demo " + std::to_string(d.demo.number)), std::string::npos) << titles;
  }
}

// The committed reel is the code's (issue 55: it was 73 commits old and lacked demo 8):
// videos/chapters.txt is, to the byte, what the reel's plan writes today; the README's demo table
// lists every demo as the program does, in the chapters' order; and the committed MP4 lasts as long
// as the plan (ffprobe). A demo added, renamed, re-described or lengthened fails it until the reel
// is rendered again (`rbsim demo all`) and the README follows.
TEST(CommittedReel, IsTheReelTheCodePlansAndTheReadmeTableAgrees) {
  if (rbsim::test::kSanitizedBuild) {
    GTEST_SKIP() << "the committed files' agreement is the normal build's to check; the sanitizers plan the real reel "
                    "in ReelChapters.TheRealReelsChaptersMeetYouTubesRules";
  }
  const std::filesystem::path source(RBSIM_SOURCE_DIR);
  const ReelOptions options;
  const ReelPlan plan = planReel(allDemos(), options);
  const std::vector<ReelChapter> chapters = reelChapters(plan, options);
  EXPECT_EQ(readFile(source / "videos" / "chapters.txt"), youtubeChapters(chapters))
      << "render the reel again: build/rbsim demo all";
  static const std::regex row(R"(^\| (\d+) \| `([a-z0-9_]+)` \| (.+) \| `videos/([a-z0-9_]+)\.mp4` \|$)");
  std::istringstream readme(readFile(source / "README.md"));
  std::vector<std::string> listed;
  for (std::string line; std::getline(readme, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    const Demo* demo = findDemo(std::stoi(m[1].str()));
    ASSERT_NE(demo, nullptr) << line;
    EXPECT_EQ(m[2].str(), demo->name) << line;
    EXPECT_EQ(m[3].str(), demo->description) << line;
    EXPECT_EQ(m[4].str(), demo->name) << line;
    listed.push_back("Demo " + m[1].str() + " " + m[2].str() + ":");  // a chapter shortens the rest
  }
  ASSERT_EQ(listed.size(), allDemos().size()) << "one README row per demo";
  std::string titles;
  for (const ReelChapter& c : chapters) titles += c.title + "\n";
  std::size_t from = 0;
  for (const std::string& demo : listed) {
    const std::size_t at = titles.find(demo, from);
    EXPECT_NE(at, std::string::npos) << demo << " is not a chapter after the one before it:\n" << titles;
    if (at != std::string::npos) from = at;
  }
  const auto [code, output] = rbsim::test::runCommand(
      "ffprobe -v error -show_entries format=duration -of csv=p=0 " +
      rbsim::test::shellQuote((source / "videos" / "rbsim-demos.mp4").string()));
  ASSERT_EQ(code, 0) << output;
  EXPECT_NEAR(std::stod(output), static_cast<double>(plan.totalFrames) / options.fps, 0.1);
}

ChapterCandidate candidate(std::size_t demo, std::uint64_t frame, const std::string& title) {
  return {demo, frame, title, "D" + std::to_string(demo)};
}

// At 10 fps: demo 0's three phases last 12.1, 11.9 and 12 s (whole seconds 13, 11, 12: the start
// second is rounded up) and keep their chapters; demo 1's second phase lasts 4 s, so demo 1 is one
// chapter; demo 3's 1 s joins demo 2 before it.
TEST(ReelChapters, ShortPhasesMergeByDemoAndShortDemosIntoTheOneBefore) {
  const std::vector<ChapterCandidate> candidates = {
      candidate(0, 0, "0a"),   candidate(0, 121, "0b"), candidate(0, 240, "0c"), candidate(1, 360, "1a"),
      candidate(1, 400, "1b"), candidate(2, 500, "2a"), candidate(2, 650, "2b"), candidate(3, 690, "3a")};
  const std::vector<ReelChapter> chapters = mergeChapters(candidates, 700, 10, 10.0);
  ASSERT_EQ(chapters.size(), 5u);
  const std::vector<std::string> titles = {"0a", "0b", "0c", "D1", "D2 / D3"};
  const std::vector<std::uint64_t> starts = {0, 121, 240, 360, 500}, ends = {121, 240, 360, 500, 700};
  const std::vector<int> seconds = {0, 13, 24, 36, 50};
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    EXPECT_EQ(chapters[i].title, titles[i]);
    EXPECT_EQ(chapters[i].startFrame, starts[i]);
    EXPECT_EQ(chapters[i].endFrame, ends[i]);
    EXPECT_EQ(chapters[i].startSecond, seconds[i]);
  }
  // 0b ends at 23.9 s but starts at second 13 and ends at 24: 11 whole seconds. At a 12 s minimum
  // it is too short, so demo 0 becomes one chapter.
  const std::vector<ReelChapter> strict = mergeChapters(candidates, 700, 10, 12.0);
  ASSERT_FALSE(strict.empty());
  EXPECT_EQ(strict.front().title, "D0");
  // A first chapter too short joins the one after it, keeping 0:00.
  const std::vector<ReelChapter> first = mergeChapters({candidate(0, 0, "D0"), candidate(1, 30, "D1"), candidate(2, 200, "D2")}, 400, 10, 10.0);
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].title, "D0 / D1");
  EXPECT_EQ(first[0].startFrame, 0u);
  EXPECT_EQ(first[1].title, "D2");
  EXPECT_EQ(youtubeChapters(first), "0:00 D0 / D1\n0:20 D2\n");
}

// YouTube's clock: M:SS under an hour, H:MM:SS from an hour on.
TEST(ReelChapters, TimesAreWrittenAsYouTubeReadsThem) {
  const std::vector<ReelChapter> chapters = {{0, 1, "Start", 0}, {1, 2, "Later", 754}, {2, 3, "Long", 3723}};
  EXPECT_EQ(youtubeChapters(chapters), "0:00 Start\n12:34 Later\n1:02:03 Long\n");
  const std::vector<TextChapter> parsed = parseYoutubeChapters(youtubeChapters(chapters));
  ASSERT_EQ(parsed.size(), 3u);
  EXPECT_EQ(parsed[2].second, 3723);
}

TEST(ProgressClock, FormatsMinutesAndHoursAndRefusesNoEstimate) {
  EXPECT_EQ(formatClock(0.0), "0:00");
  EXPECT_EQ(formatClock(7.4), "0:07");
  EXPECT_EQ(formatClock(59.6), "1:00");  // rounded to whole seconds
  EXPECT_EQ(formatClock(754.0), "12:34");
  EXPECT_EQ(formatClock(3723.0), "1:02:03");
  EXPECT_EQ(formatClock(-1.0), "--:--");
  EXPECT_EQ(formatClock(std::nan("")), "--:--");
  EXPECT_EQ(formatClock(INFINITY), "--:--");
}

TEST(ProgressLine, EtaIsTheFramesLeftAtTheMeanRateSoFar) {
  // 250 of 1000 frames in 10 s: 25 fps, so the 750 left take 30 s.
  const std::string line = progressLine({3, 6, "broadphase", 250, 1000, 10.0});
  EXPECT_NE(line.find("demo 3/6 broadphase"), std::string::npos) << line;
  EXPECT_NE(line.find("frames 250/1000 (25.0%)"), std::string::npos) << line;
  EXPECT_NE(line.find("25.0 fps"), std::string::npos) << line;
  EXPECT_NE(line.find("elapsed 0:10"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:30"), std::string::npos) << line;
  // No frame yet: no rate, so no estimate rather than an infinite or zero one.
  EXPECT_NE(progressLine({1, 6, "particles", 0, 1000, 2.0}).find("ETA --:--"), std::string::npos);
  EXPECT_NE(progressLine({6, 6, "soft", 1000, 1000, 80.0}).find("ETA 0:00"), std::string::npos);
}

TEST(ProgressLine, ARunWithoutImagesCountsStepsPerPhase) {
  ProgressState state{2, 3, "contact_solvers", 500, 2000, 5.0};
  state.kind = "phase";
  state.unit = "steps";
  const std::string line = progressLine(state);
  EXPECT_NE(line.find("phase 2/3 contact_solvers  steps 500/2000 (25.0%)  100.0 steps/s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:15"), std::string::npos) << line;
}

// Frame k shows the step nearest k/fps: its time is off by at most dt/2 and never drifts, and a
// scene has a frame for every 1/fps of its duration, also when dt does not divide 1/fps.
TEST(FrameTiming, FramesKeepTimeWithinHalfAStepAtSixtyFps) {
  constexpr double fps = 60.0;
  constexpr double duration = 3.0;  // [s]
  for (const double dt : {1.0 / 240.0, 1.0 / 120.0, 1.0 / 60.0, 0.007, 0.003, 1.0 / 50.0}) {
    const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
    const std::uint64_t frames = frameCount(steps, fps, dt);
    const double shownDuration = static_cast<double>(steps) * dt;
    // Every frame time k/fps before the last step's time + dt/2 (none of these lands exactly on it).
    EXPECT_EQ(frames, static_cast<std::uint64_t>(std::floor((shownDuration + 0.5 * dt) * fps)) + 1) << "dt " << dt;
    for (std::uint64_t k = 0; k < frames; ++k) {
      const double error = static_cast<double>(stepOfFrame(k, fps, dt)) * dt - static_cast<double>(k) / fps;
      ASSERT_LE(std::abs(error), 0.5 * dt + 1e-12) << "dt " << dt << " frame " << k;
    }
  }
}

// The demos the short reel below is made of: every demo, but under the sanitizers not demos 4
// and 6, whose meshes and grids (mesh_contact, sdf_bowl, csg_cup) took most of its 43 s there:
// Shipped/EveryScene loads and steps those scenes there, and the reel's code is the same for any
// demos (the normal build makes the reel of all of them).
std::vector<Demo> shortReelDemos() {
  std::vector<Demo> demos;
  for (const Demo& d : allDemos()) {
    if (!rbsim::test::kSanitizedBuild || (d.number != 4 && d.number != 6)) demos.push_back(d);
  }
  return demos;
}

// A cut-down reel of every demo (0.1 s of each scene, 3-frame cards, 320x180): the plan's
// counts must be the frames the run produced, per demo (its PNGs) and in the reel's MP4.
TEST(Reel, PlanMatchesTheFramesAShortRunWrites) {
  // Per process: two builds' suites may run at once on one machine.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rbsim_reel_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ReelOptions options;
  options.width = 320;
  options.height = 180;
  options.cardSeconds = 0.05;  // 3 frames at 60 fps
  options.overrides = {"world.duration=0.1"};
  options.framesBase = dir / "frames";
  options.writeFrames = true;
  options.videoDir = dir / "videos";
  options.quiet = true;
  // Every phase its own chapter, with no minimum length (YouTube's 10 s is for the real reel,
  // tested above; here the last demo's chapters even start, rounded up to whole seconds, after
  // this 3.2 s reel ends): the muxed chapters' times are then checked at every phase boundary,
  // and titles with '=' (demo 5's "dt = 1/60 s") go through FFMETADATA's escaping.
  options.minChapterSeconds = -std::numeric_limits<double>::infinity();
  const std::vector<Demo> demos = shortReelDemos();
  const ReelPlan plan = planReel(demos, options);
  ASSERT_EQ(plan.demos.size(), demos.size());
  EXPECT_EQ(plan.cardFrames, 3u);
  std::uint64_t sum = plan.cardFrames;
  for (const ReelDemo& d : plan.demos) {
    // Each scene: 0.1 s at 60 fps is frames 0..6, whatever its time step.
    EXPECT_EQ(d.frames, 7u * d.phases.size()) << d.demo.name;
    sum += plan.cardFrames + d.frames;
  }
  EXPECT_EQ(plan.totalFrames, sum);

  const ReelResult result = renderReel(plan, options);
  ASSERT_EQ(result.videos.size(), plan.demos.size() + 1);
  for (std::size_t i = 0; i < plan.demos.size(); ++i) {
    const std::string& name = plan.demos[i].demo.name;
    EXPECT_EQ(result.videos[i].frames, plan.demos[i].frames) << name;
    std::uint64_t pngs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(options.framesBase / name)) {
      pngs += entry.path().extension() == ".png";
    }
    EXPECT_EQ(pngs, plan.demos[i].frames) << name;
    EXPECT_GT(result.videos[i].bytes, 0u) << name;
  }
  EXPECT_EQ(result.videos.back().frames, plan.totalFrames);
  EXPECT_EQ(result.cardImages.size(), plan.demos.size() + 1);

  // What ffmpeg wrote, counted by ffprobe: every planned frame is in the reel.
  const std::string command = "ffprobe -v error -select_streams v:0 -count_packets -show_entries stream=nb_read_packets "
                              "-of csv=p=0 '" + (options.videoDir / options.reelFile).string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  unsigned long long packets = 0;
  EXPECT_EQ(std::fscanf(pipe, "%llu", &packets), 1);
  pclose(pipe);
  EXPECT_EQ(packets, plan.totalFrames);
  // The parts are joined without re-encoding: their timestamps must follow on, so the reel lasts
  // its frames at 60 fps (a gap or an overlap at a join would show here), within a frame.
  const std::string probe = "ffprobe -v error -select_streams v:0 -show_entries stream=duration -of csv=p=0 '" +
                            (options.videoDir / options.reelFile).string() + "'";
  FILE* durationPipe = popen(probe.c_str(), "r");
  ASSERT_NE(durationPipe, nullptr);
  double seconds = 0.0;
  EXPECT_EQ(std::fscanf(durationPipe, "%lf", &seconds), 1);
  pclose(durationPipe);
  EXPECT_NEAR(seconds, static_cast<double>(plan.totalFrames) / options.fps, 1.0 / options.fps);

  // The chapters: in chapters.txt beside the reel, in YouTube's format, and in the MP4 as ffprobe
  // reads them, one per phase, each starting where the plan's frames say within one frame.
  const std::vector<std::uint64_t> starts = phaseStartFrames(plan);
  EXPECT_EQ(result.chaptersPath, options.videoDir / "chapters.txt");
  const std::vector<TextChapter> text = parseYoutubeChapters(readFile(options.videoDir / "chapters.txt"));
  FILE* chapterPipe = popen(("ffprobe -v error -show_chapters -of json '" + (options.videoDir / options.reelFile).string() + "'").c_str(), "r");
  ASSERT_NE(chapterPipe, nullptr);
  std::string probed;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, chapterPipe)) probed.append(buffer, n);
  pclose(chapterPipe);
  const nlohmann::json muxed = nlohmann::json::parse(probed, nullptr, false).value("chapters", nlohmann::json::array());
  ASSERT_EQ(muxed.size(), starts.size()) << probed;
  ASSERT_EQ(text.size(), starts.size());
  const double frame = 1.0 / options.fps;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const double start = static_cast<double>(starts[i]) * frame;
    const double end = i + 1 < starts.size() ? static_cast<double>(starts[i + 1]) * frame : seconds;
    const std::string title = muxed[i]["tags"].value("title", "");
    EXPECT_NEAR(std::stod(muxed[i]["start_time"].get<std::string>()), start, frame) << title;
    EXPECT_NEAR(std::stod(muxed[i]["end_time"].get<std::string>()), end, frame) << title;
    EXPECT_EQ(title, text[i].title);
    EXPECT_EQ(text[i].second, static_cast<long long>(std::ceil(start - 1e-9))) << title;
  }
  EXPECT_EQ(text.front().second, 0);
  EXPECT_NE(probed.find("dt = 1/60 s"), std::string::npos) << probed;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rbsim::app
