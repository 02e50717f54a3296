// `rbsim demo all`: the frame plan (title cards + every demo's frames) is what a short run of the
// reel really writes, frames keep time at 60 fps whatever the time step, and the progress line's
// clock and ETA read right.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "demos/demo.h"
#include "run/progress.h"
#include "run/reel.h"
#include "run/runner.h"

namespace rbsim::app {
namespace {

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
  options.videoDir = dir / "videos";
  options.quiet = true;
  const ReelPlan plan = planReel(allDemos(), options);
  ASSERT_EQ(plan.demos.size(), allDemos().size());
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
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rbsim::app
