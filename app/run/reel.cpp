#include "run/reel.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "rbsim/io/input_error.h"
#include "run/paths.h"
#include "render/checked_file.h"
#include "render/frame_sink.h"
#include "render/png_sequence_writer.h"
#include "render/render_error.h"
#include "render/title_card.h"
#include "render/video_concat.h"
#include "run/output_budget.h"
#include "run/progress.h"
#include "run/runner.h"

namespace rbsim::app {

namespace {

using Clock = std::chrono::steady_clock;

// Cards fade in from black and out to black over this time [s]: a cut from a still card
// straight into a moving scene looks like a glitch.
constexpr double kFadeSeconds = 0.3;

std::string seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f s", s);
  return buffer;
}

// "Demo 1 (a): a fountain on the ground" -> "a fountain on the ground": the card already names
// the demo.
std::string phaseCaption(const std::string& title) {
  const std::size_t colon = title.find(": ");
  return colon == std::string::npos ? title : title.substr(colon + 2);
}

std::string formatLine(const ReelOptions& o) {
  return std::to_string(o.width) + "\xc3\x97" + std::to_string(o.height) + "  \xc2\xb7  " + std::to_string(o.fps) +
         " fps  \xc2\xb7  H.264";  // U+00D7 multiplication sign, U+00B7 middle dot (in DejaVu)
}

double demoSeconds(const ReelDemo& d, int fps) { return static_cast<double>(d.frames) / fps; }

render::TitleCard openingCard(const ReelPlan& plan, const ReelOptions& options) {
  std::size_t scenes = 0;
  for (const ReelDemo& d : plan.demos) scenes += d.phases.size();
  render::TitleCard card;
  card.kicker = "RBSIM  \xc2\xb7  DEMO REEL";
  card.title = "Physically based animation";
  card.description = "Every numbered coursework demo, simulated by rbsim's engine and rendered off-screen by its own "
                     "renderer: " + std::to_string(plan.demos.size()) + " demos, " + std::to_string(scenes) +
                     " scenes, " + formatClock(static_cast<double>(plan.totalFrames) / options.fps) + " in all.";
  card.listHeading = "DEMOS";
  for (const ReelDemo& d : plan.demos) {
    card.list.push_back({std::to_string(d.demo.number), d.demo.name, d.demo.description, seconds(demoSeconds(d, options.fps))});
  }
  card.footerLeft = "rbsim  \xc2\xb7  rigid-body simulator";
  card.footerRight = formatLine(options);
  return card;
}

render::TitleCard demoCard(const ReelPlan& plan, std::size_t index, const ReelOptions& options) {
  const ReelDemo& d = plan.demos[index];
  render::TitleCard card;
  card.kicker = "DEMO " + std::to_string(index + 1) + " OF " + std::to_string(plan.demos.size());
  card.number = std::to_string(d.demo.number);
  card.title = d.demo.name;
  card.description = d.demo.description;
  card.description[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(card.description[0])));
  card.listHeading = d.phases.size() == 1 ? "SCENE" : "PHASES";
  for (std::size_t p = 0; p < d.phases.size(); ++p) {
    const Phase& phase = d.phases[p];
    card.list.push_back({std::to_string(p + 1), phaseCaption(phase.scene().title), "",
                         seconds(static_cast<double>(frameCount(phase)) / options.fps)});
  }
  card.footerLeft = "rbsim demo " + std::to_string(d.demo.number) + "  \xc2\xb7  videos/" + d.demo.name + ".mp4";
  card.footerRight = formatLine(options);
  return card;
}

// The card's frame `k` of `count`, faded from and to black.
std::vector<std::uint8_t> fadedFrame(const std::vector<std::uint8_t>& card, std::uint64_t k, std::uint64_t count,
                                     int fps) {
  const double t = (static_cast<double>(k) + 0.5) / fps, end = static_cast<double>(count) / fps;
  const double gain = std::clamp(std::min(t, end - t) / kFadeSeconds, 0.0, 1.0);
  std::vector<std::uint8_t> frame(card);
  if (gain >= 1.0) return frame;
  for (std::size_t i = 0; i < frame.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) frame[i + c] = static_cast<std::uint8_t>(std::lround(gain * frame[i + c]));
  }
  return frame;
}

std::uintmax_t fileSize(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return error ? 0 : size;
}

std::string demoChapterTitle(const Demo& demo) {
  // The description up to its first colon: demo 2's goes on to list its phases.
  const std::string& d = demo.description;
  return "Demo " + std::to_string(demo.number) + " " + demo.name + ": " + d.substr(0, d.find(':'));
}

// The frame time as the MP4's chapters count it, in ms (TIMEBASE=1/1000), nearest.
std::int64_t frameMs(std::uint64_t frame, int fps) {
  return static_cast<std::int64_t>(std::llround(static_cast<double>(frame) * 1000.0 / fps));
}

}  // namespace

std::vector<ChapterCandidate> chapterCandidates(const ReelPlan& plan) {
  std::vector<ChapterCandidate> candidates;
  std::uint64_t frame = plan.cardFrames;  // after the opening card
  for (std::size_t i = 0; i < plan.demos.size(); ++i) {
    const ReelDemo& d = plan.demos[i];
    const std::uint64_t cardStart = frame;
    frame += plan.cardFrames;
    for (std::size_t p = 0; p < d.phases.size(); ++p) {
      ChapterCandidate c;
      c.demo = i;
      c.startFrame = p > 0 ? frame : i > 0 ? cardStart : 0;
      c.demoTitle = demoChapterTitle(d.demo);
      c.title = d.phases.size() == 1 ? c.demoTitle
                                     : "Demo " + std::to_string(d.demo.number) + " (" + static_cast<char>('a' + p % 26) +
                                           "): " + phaseCaption(d.phases[p].scene().title);
      candidates.push_back(std::move(c));
      frame += frameCount(d.phases[p]);
    }
  }
  return candidates;
}

std::vector<ReelChapter> mergeChapters(const std::vector<ChapterCandidate>& candidates, std::uint64_t totalFrames,
                                       int fps, double minSeconds) {
  if (fps <= 0) throw InputError("", "fps", "expected a positive frame rate");
  const auto second = [&](std::uint64_t frame) {
    return static_cast<int>((frame + static_cast<std::uint64_t>(fps) - 1) / static_cast<std::uint64_t>(fps));
  };
  const double videoSeconds = static_cast<double>(totalFrames) / fps;
  // Lengths as YouTube counts them: whole-second start to the next whole-second start.
  const auto lengths = [&](const std::vector<ReelChapter>& list) {
    std::vector<double> out;
    for (std::size_t i = 0; i < list.size(); ++i) {
      out.push_back((i + 1 < list.size() ? list[i + 1].startSecond : videoSeconds) - list[i].startSecond);
    }
    return out;
  };
  // Per phase, for every demo; then a demo with a phase too short becomes one chapter.
  std::vector<ReelChapter> perPhase;
  for (const ChapterCandidate& c : candidates) perPhase.push_back({c.startFrame, 0, c.title, second(c.startFrame)});
  const std::vector<double> phaseLengths = lengths(perPhase);
  std::vector<ReelChapter> chapters;
  for (std::size_t i = 0; i < candidates.size();) {
    std::size_t j = i;
    bool longEnough = true;
    for (; j < candidates.size() && candidates[j].demo == candidates[i].demo; ++j) {
      longEnough = longEnough && phaseLengths[j] >= minSeconds;
    }
    if (longEnough) {
      chapters.insert(chapters.end(), perPhase.begin() + static_cast<std::ptrdiff_t>(i),
                      perPhase.begin() + static_cast<std::ptrdiff_t>(j));
    } else {
      chapters.push_back({candidates[i].startFrame, 0, candidates[i].demoTitle, second(candidates[i].startFrame)});
    }
    i = j;
  }
  // A demo still too short joins its neighbour: the one before, or for the first the one after.
  for (;;) {
    const std::vector<double> length = lengths(chapters);
    std::size_t k = 0;
    while (k < chapters.size() && length[k] >= minSeconds) ++k;
    if (k == chapters.size() || chapters.size() < 2) break;
    const std::size_t into = k == 0 ? 0 : k - 1;
    chapters[into].title += " / " + chapters[into + 1].title;
    chapters.erase(chapters.begin() + static_cast<std::ptrdiff_t>(into + 1));
  }
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    chapters[i].endFrame = i + 1 < chapters.size() ? chapters[i + 1].startFrame : totalFrames;
  }
  return chapters;
}

std::vector<ReelChapter> reelChapters(const ReelPlan& plan, const ReelOptions& options) {
  return mergeChapters(chapterCandidates(plan), plan.totalFrames, options.fps, options.minChapterSeconds);
}

std::string youtubeChapters(const std::vector<ReelChapter>& chapters) {
  std::string text;
  for (const ReelChapter& c : chapters) text += formatClock(c.startSecond) + " " + c.title + "\n";
  return text;
}

ReelPlan planReel(const std::vector<Demo>& demos, const ReelOptions& options) {
  if (options.cardSeconds <= 0.0) throw InputError("", "card seconds", "expected a positive time");
  std::vector<std::string> overrides = {"view.fps=" + std::to_string(options.fps),
                                        "view.size=[" + std::to_string(options.width) + "," + std::to_string(options.height) + "]"};
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  ReelPlan plan;
  plan.cardFrames = static_cast<std::uint64_t>(std::llround(options.cardSeconds * options.fps));
  plan.totalFrames = plan.cardFrames;  // the opening card
  for (const Demo& demo : demos) {
    ReelDemo entry{demo, {}, 0};
    for (const std::string& file : demo.scenes) {
      entry.phases.push_back(loadPhase(assetDir() + "/scenes/" + file, overrides));
      checkStepCounts(entry.phases.back());
      entry.frames += frameCount(entry.phases.back());  // each at most kHugeCount: no wrap
    }
    plan.totalFrames += plan.cardFrames + entry.frames;
    plan.demos.push_back(std::move(entry));
  }
  std::uint64_t demoFrames = 0;  // the PNGs: every demo's frames, without the cards
  for (const ReelDemo& d : plan.demos) demoFrames += d.frames;
  checkOutputBudget("", "`demo all`, every demo and its title card, at view.fps " + std::to_string(options.fps),
                    plan.totalFrames, options.width, options.height, options.fps, "", options.pngLevel);
  if (options.writeFrames) {
    checkOutputBudget("", "", demoFrames, options.width, options.height, options.fps, options.framesBase.string(),
                      options.pngLevel);
  }
  return plan;
}

ReelResult renderReel(const ReelPlan& plan, const ReelOptions& options) {
  const auto wallStart = Clock::now();
  ReelResult result;
  const std::filesystem::path reelPath = options.videoDir / options.reelFile;
  render::ensureWritableDirectory(options.videoDir);  // before any frame, not after minutes
  // The reel is its parts joined without encoding again (video_concat.h): each card becomes a
  // clip beside its still, each demo its own video, and every frame is encoded once.
  std::vector<std::filesystem::path> parts;
  // Each card's clip is encoded while the next demo renders; they are waited for before joining.
  std::vector<std::unique_ptr<render::FrameSink>> clips;
  render::TitleCardRenderer cards(options.width, options.height, options.glBackend);
  ProgressMeter meter(stderr, isTerminal(stderr), options.quiet);

  std::uint64_t done = 0;
  std::size_t item = 0;
  std::string name = "(opening card)";
  const auto report = [&](bool force = false) {
    meter.update({item, plan.demos.size(), name, done, plan.totalFrames,
                  std::chrono::duration<double>(Clock::now() - wallStart).count()},
                 force);
  };
  const auto playCard = [&](const render::TitleCard& card, const std::string& still) {
    const std::vector<std::uint8_t>& image = cards.render(card);
    const std::filesystem::path path = options.framesBase / "cards" / (still + ".png");
    render::ensureWritableDirectory(path.parent_path());
    render::writePng(path, options.width, options.height, image);
    result.cardImages.push_back(path);
    render::SinkOptions clip;
    clip.videoPath = options.framesBase / "cards" / (still + ".mp4");
    clip.fps = options.fps;
    clip.width = options.width;
    clip.height = options.height;
    auto sink = std::make_unique<render::FrameSink>(clip);
    for (std::uint64_t k = 0; k < plan.cardFrames; ++k) {
      sink->submit(fadedFrame(image, k, plan.cardFrames, options.fps));
      ++done;
      report();
    }
    sink->closeInput();
    clips.push_back(std::move(sink));
    parts.push_back(*clip.videoPath);
  };

  playCard(openingCard(plan, options), "00_opening");
  for (std::size_t i = 0; i < plan.demos.size(); ++i) {
    const ReelDemo& d = plan.demos[i];
    item = i + 1;
    name = d.demo.name;
    char still[64];
    std::snprintf(still, sizeof still, "%02zu_", item);
    playCard(demoCard(plan, i, options), still + d.demo.name);
    RunOptions run;
    if (options.writeFrames) run.framesDir = (options.framesBase / d.demo.name).string();
    run.videoPath = (options.videoDir / (d.demo.name + ".mp4")).string();
    run.pngLevel = options.pngLevel;
    run.glBackend = options.glBackend;
    run.quiet = true;
    const RunSummary summary =
        runPhases(d.phases, run, "Demo " + std::to_string(d.demo.number) + ": " + d.demo.name,
                  [&](const std::vector<std::uint8_t>&) {
                    ++done;
                    report();
                  });
    parts.push_back(run.videoPath);
    result.videos.push_back({run.videoPath, summary.frames, static_cast<double>(summary.frames) / options.fps,
                             fileSize(run.videoPath)});
  }
  for (const std::unique_ptr<render::FrameSink>& sink : clips) sink->finish();
  // Chapters from the frame plan, the frames just rendered: no probing of what ffmpeg wrote.
  result.chapters = reelChapters(plan, options);
  std::vector<render::VideoChapter> muxed;
  for (const ReelChapter& c : result.chapters) {
    muxed.push_back({frameMs(c.startFrame, options.fps), frameMs(c.endFrame, options.fps), c.title});
  }
  render::concatVideos(parts, reelPath, muxed);
  result.chaptersPath = options.videoDir / options.chaptersFile;
  render::CheckedFile chaptersFile;
  if (!chaptersFile.open(result.chaptersPath) || !chaptersFile.write(youtubeChapters(result.chapters)) ||
      !chaptersFile.close()) {
    throw render::RenderError("could not write " + result.chaptersPath.string() + ": " + chaptersFile.error());
  }
  report(true);
  meter.finish();
  result.videos.push_back({reelPath, done, static_cast<double>(done) / options.fps, fileSize(reelPath)});
  result.wallSeconds = std::chrono::duration<double>(Clock::now() - wallStart).count();
  return result;
}

void printReelSummary(const ReelResult& result, const ReelOptions& options) {
  if (options.quiet) return;
  for (const VideoReport& v : result.videos) {
    std::printf("%-28s %7.2f s  %6llu frames  %6.1f MB\n", v.path.string().c_str(), v.seconds,
                static_cast<unsigned long long>(v.frames), static_cast<double>(v.bytes) / 1e6);
  }
  if (!result.chaptersPath.empty()) {
    std::printf("chapters: %s (YouTube's format, also in the reel's MP4):\n", result.chaptersPath.string().c_str());
    for (const ReelChapter& c : result.chapters) {
      std::printf("  %s %s\n", formatClock(c.startSecond).c_str(), c.title.c_str());
    }
    if (result.chapters.size() < 3) {
      std::printf("  (YouTube shows chapters only from 3 on, each at least 10 s long)\n");
    }
  }
  if (!result.cardImages.empty()) std::printf("title cards: %s\n", result.cardImages.front().parent_path().string().c_str());
  std::printf("frames: %s/<name>/\n", options.framesBase.string().c_str());
  std::printf("wall time %s (%.1f s)\n", formatClock(result.wallSeconds).c_str(), result.wallSeconds);
}

}  // namespace rbsim::app
