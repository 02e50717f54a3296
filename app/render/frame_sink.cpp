#include "frame_sink.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "png_sequence_writer.h"
#include "render_error.h"
#include "video_encoder.h"

namespace rbsim::render {

std::size_t queueFramesWithin(std::size_t wanted, int width, int height) {
  const std::size_t frameBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  const std::size_t fit = frameBytes > 0 ? kMaxQueuedBytesPerWriter / frameBytes : wanted;
  return std::max<std::size_t>(1, std::min(wanted, fit));
}

FrameSink::FrameSink(SinkOptions options) : options_(std::move(options)) {
  if (options_.width <= 0 || options_.height <= 0 || options_.fps <= 0) {
    throw RenderError("frame output: width, height and fps must be positive (got " +
                      std::to_string(options_.width) + "x" + std::to_string(options_.height) +
                      " at " + std::to_string(options_.fps) + " fps)");
  }
  options_.queueFrames = queueFramesWithin(options_.queueFrames, options_.width, options_.height);
  // The PNG folder first: checking it is cheap, and a bad one then stops the run before ffmpeg
  // has started (and created an empty video).
  if (options_.pngDir) {
    png_ = std::make_unique<PngSequenceWriter>(*options_.pngDir, options_.width, options_.height,
                                               options_.pngLevel, options_.pngThreads,
                                               options_.queueFrames);
  }
  if (options_.videoPath) {
    video_ = std::make_unique<VideoEncoder>(*options_.videoPath, options_.width,
                                            options_.height, options_.fps, options_.queueFrames);
  }
}

FrameSink::~FrameSink() {
  // Not finished: the run failed. Its video is thrown away (the last run's stays); its PNG frames
  // each appeared whole as they were written.
  if (video_) video_->abandon();
  try {
    if (png_) png_->finish();
  } catch (...) {
    // Destructors must not throw; callers who care call finish() themselves.
  }
}

void FrameSink::submit(std::vector<std::uint8_t> rgbaTopDown) {
  submit(std::make_shared<const std::vector<std::uint8_t>>(std::move(rgbaTopDown)));
}

void FrameSink::submit(std::shared_ptr<const std::vector<std::uint8_t>> rgbaTopDown) {
  const std::size_t expected =
      static_cast<std::size_t>(options_.width) * static_cast<std::size_t>(options_.height) * 4;
  if (rgbaTopDown == nullptr || rgbaTopDown->size() != expected) {
    throw RenderError("frame output: image has " + std::to_string(rgbaTopDown ? rgbaTopDown->size() : 0) +
                      " bytes, expected " + std::to_string(expected));
  }
  // A writer that already failed would drop every further frame: stop the run now instead.
  if (video_) {
    if (std::string error = video_->error(); !error.empty()) throw RenderError(error);
  }
  if (png_) {
    if (std::string error = png_->error(); !error.empty()) throw RenderError(error);
  }
  OutputFrame frame{frames_++, std::move(rgbaTopDown)};
  const auto start = std::chrono::steady_clock::now();
  if (video_) video_->submit(frame);
  if (png_) png_->submit(std::move(frame));
  blockedMs_.add(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

void FrameSink::closeInput() {
  if (video_) video_->closeInput();
  if (png_) png_->closeInput();
}

void FrameSink::finish() {
  // Finish both even if one fails, then report the video first (its message says more).
  std::string error;
  if (video_) {
    try {
      video_->finish();
    } catch (const RenderError& e) {
      error = e.what();
    }
  }
  if (png_) {
    try {
      png_->finish();
    } catch (const RenderError& e) {
      if (error.empty()) error = e.what();
    }
  }
  if (!error.empty()) throw RenderError(error);
}

SinkTiming FrameSink::timing() const {
  SinkTiming t;
  t.frames = frames_;
  t.pngMs = png_ ? png_->meanWriteMs() : 0.0;
  t.videoMs = video_ ? video_->meanWriteMs() : 0.0;
  t.blockedMs = blockedMs_.mean();
  return t;
}

}  // namespace rbsim::render
