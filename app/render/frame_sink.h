#pragma once
// Where rendered images go: numbered PNGs and/or an H.264 MP4, written in the background so the
// simulation never waits for encoding (unless the bounded queues are full).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "png_file.h"
#include "timing.h"

namespace rbsim::render {

struct SinkOptions {
  std::optional<std::filesystem::path> pngDir;     // frame_000000.png ... written here
  std::optional<std::filesystem::path> videoPath;  // e.g. videos/demo1.mp4 (folders created)
  int fps = 30;
  int width = 0;   // must match the images submitted
  int height = 0;
  int pngLevel = kDefaultPngLevel;  // zlib level in [0, 9]; see png_file.h for measured costs
  int pngThreads = 2;
  std::size_t queueFrames = 8;  // per writer; 8 frames of 1280x720 RGBA is 30 MB
};

// Bytes of images one writer's queue may hold: 8 frames of 1920x1080 (66 MB). Larger images get
// a shorter queue (at least one frame), so an 8192x8192 run (268 MB a frame) holds ~0.5 GB in its
// two queues instead of 4.3 GB.
inline constexpr std::size_t kMaxQueuedBytesPerWriter = std::size_t{8} * 1920 * 1080 * 4;  // [B]

// How many frames of width x height RGBA one writer may queue: `wanted`, fewer if that would
// pass kMaxQueuedBytesPerWriter, never fewer than 1.
std::size_t queueFramesWithin(std::size_t wanted, int width, int height);

class PngSequenceWriter;
class VideoEncoder;

class FrameSink {
 public:
  // Creates the folders and starts ffmpeg before any frame exists, so a missing ffmpeg or an
  // unwritable path fails at once. Throws RenderError naming the path or program.
  explicit FrameSink(SinkOptions options);
  ~FrameSink();  // without finish(): the run failed; abandons the video (VideoEncoder::abandon)
  FrameSink(const FrameSink&) = delete;
  FrameSink& operator=(const FrameSink&) = delete;

  // Takes one top-down RGBA8 image of width*height*4 bytes. Returns at once unless a queue is
  // full. Throws RenderError if a writer has already failed (e.g. ffmpeg exited).
  void submit(std::vector<std::uint8_t> rgbaTopDown);
  // The same without a copy: the writers share the image until they are done with it.
  void submit(std::shared_ptr<const std::vector<std::uint8_t>> rgbaTopDown);
  // No more frames: the writers finish in the background while the caller goes on; finish()
  // then waits for them and reports. No submit() after it.
  void closeInput();
  // Flushes every queue, closes ffmpeg's input and waits for it. Throws RenderError if any PNG
  // failed or ffmpeg exited with a non-zero status (its error output is in the message).
  void finish();
  SinkTiming timing() const;
  long frames() const { return frames_; }

 private:
  SinkOptions options_;
  std::unique_ptr<PngSequenceWriter> png_;
  std::unique_ptr<VideoEncoder> video_;
  long frames_ = 0;
  MeanMs blockedMs_;
};

}  // namespace rbsim::render
