#pragma once
// `rbsim demo all`: every numbered demo in registry order, each into its own video and PNG
// folder as `rbsim demo N` would, and the same frames, each demo after a title card and the
// whole after an opening card, into one reel (videos/rbsim-demos.mp4), all in one format.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "demos/demo.h"
#include "render/gl_context.h"
#include "render/png_file.h"
#include "run/phase.h"

namespace rbsim::app {

struct ReelOptions {
  int width = 1280;  // image size [px], forced on every scene (view.size)
  int height = 720;
  int fps = 60;               // frames per second, forced on every scene (view.fps)
  double cardSeconds = 2.5;   // time each title card stays on screen [s]
  std::vector<std::string> overrides;  // the user's scene assignments, applied after the format
  // The title cards' stills and clips go to framesBase/cards/; with writeFrames (--frames DIR),
  // demo <name>'s PNGs go to framesBase/<name>/. PNGs are off by default: at 1280x720 one took
  // 15-23 ms to encode against x264's 8.5 ms a frame, the reel's largest cost (issue 38).
  std::filesystem::path framesBase = "build/frames";
  bool writeFrames = false;
  std::filesystem::path videoDir = "videos";          // <name>.mp4 and the reel go here
  std::string reelFile = "rbsim-demos.mp4";
  // The reel's chapters in YouTube's description format ("0:00 Title" a line), beside the reel;
  // the same chapters are muxed into the reel's MP4.
  std::string chaptersFile = "chapters.txt";
  // YouTube shows a video's chapters only if each lasts at least 10 s (and there are at least
  // three, the first at 0:00; YouTube Help, "Video chapters"): shorter ones are merged
  // (mergeChapters). Minus infinity keeps every phase's chapter, however short.
  double minChapterSeconds = 10.0;
  int pngLevel = render::kDefaultPngLevel;  // zlib level of the PNG frames (--png-level)
  render::GlBackend glBackend = render::defaultGlBackend();  // --gl
  bool quiet = false;  // no progress and no summary
};

struct ReelDemo {
  Demo demo;
  std::vector<Phase> phases;  // its scenes, loaded with the reel's format and the user's overrides
  std::uint64_t frames = 0;   // rendered for its phases (frameCount of each, summed)
};

struct ReelPlan {
  std::vector<ReelDemo> demos;
  std::uint64_t cardFrames = 0;   // of one title card
  std::uint64_t totalFrames = 0;  // of the reel: opening card, then each demo's card and frames
};

// Loads every demo's scenes (bad input fails here, before anything renders), counts frames and
// checks them against output_budget.h's limits.
ReelPlan planReel(const std::vector<Demo>& demos, const ReelOptions& options);

// A chapter of the reel: frames [startFrame, endFrame) of the frame plan.
struct ReelChapter {
  std::uint64_t startFrame = 0;
  std::uint64_t endFrame = 0;
  std::string title;
  // As chapters.txt writes it: the first whole second at or after startFrame, so that a click on
  // the chapter lands inside it (in its title card), not in the end of the one before.
  int startSecond = 0;
};

// A place where a chapter may start, in frame-plan order: each demo phase (the first one with its
// demo's title card before it, the very first with the opening card too, so it starts at 0).
struct ChapterCandidate {
  std::size_t demo = 0;  // index into the plan's demos
  std::uint64_t startFrame = 0;
  std::string title;       // the phase's chapter title
  std::string demoTitle;   // the title of its demo's chapter, if its phases are merged
};

// The candidates of a plan: the same order and frame counts renderReel plays.
std::vector<ChapterCandidate> chapterCandidates(const ReelPlan& plan);

// Chapters from candidates, each at least minSeconds long in whole seconds as chapters.txt and
// YouTube count them (from its start second to the next one's, the last to totalFrames / fps):
// a demo gets a chapter per phase if every one of them is long enough, else one chapter (its
// demoTitle); a demo chapter still too short is merged into the one before it (the first into the
// one after), the titles joined by " / ".
std::vector<ReelChapter> mergeChapters(const std::vector<ChapterCandidate>& candidates, std::uint64_t totalFrames,
                                       int fps, double minSeconds);

// The chapters of a plan: mergeChapters(chapterCandidates(plan), ...).
std::vector<ReelChapter> reelChapters(const ReelPlan& plan, const ReelOptions& options);

// chapters.txt's text: "M:SS Title" (H:MM:SS from an hour on) a line, as YouTube reads chapters
// from a video's description.
std::string youtubeChapters(const std::vector<ReelChapter>& chapters);

struct VideoReport {
  std::filesystem::path path;
  std::uint64_t frames = 0;
  double seconds = 0.0;      // frames / fps
  std::uintmax_t bytes = 0;  // file size after ffmpeg finished
};

struct ReelResult {
  std::vector<VideoReport> videos;  // each demo's, in order, then the reel
  std::vector<std::filesystem::path> cardImages;  // one PNG still of each title card
  std::vector<ReelChapter> chapters;              // in chapters.txt and in the reel's MP4
  std::filesystem::path chaptersPath;
  double wallSeconds = 0.0;
};

// Renders the plan; progress goes to stderr (see progress.h) unless options.quiet.
ReelResult renderReel(const ReelPlan& plan, const ReelOptions& options);

// "videos/particles.mp4  24.02 s  1441 frames  3.1 MB" per video, then the wall time.
void printReelSummary(const ReelResult& result, const ReelOptions& options);

}  // namespace rbsim::app
