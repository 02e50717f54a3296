#pragma once
// H.264 MP4 through the ffmpeg program: raw RGBA frames go to its stdin from a writer thread fed
// by a bounded queue, so encoding overlaps the simulation and memory stays bounded.
#include <filesystem>
#include <mutex>
#include <string>
#include <sys/types.h>
#include <thread>

#include "bounded_queue.h"
#include "output_frame.h"
#include "timing.h"

namespace rbsim::render {

class VideoEncoder {
 public:
  // Creates the output's parent folders, checks the file can be written and starts ffmpeg.
  // Throws RenderError if ffmpeg is not on PATH or the path cannot be written (names it).
  VideoEncoder(std::filesystem::path output, int width, int height, int fps,
               std::size_t queueFrames);
  ~VideoEncoder();  // finishes, swallowing errors (call finish() to see them)
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  void submit(OutputFrame frame);  // blocks only while the queue is full
  // No more frames: ffmpeg gets end-of-file once the queue has drained and finishes the file on
  // its own; finish() then only waits. No submit() after it.
  void closeInput() { queue_.close(); }
  // Closes ffmpeg's input and waits for it; throws RenderError with ffmpeg's exit status and
  // its error output when it failed.
  void finish();
  // Empty while all is well; otherwise why frames are being dropped (ffmpeg died early).
  std::string error() const;
  double meanWriteMs() const { return writeMs_.mean(); }

 private:
  void spawn();
  void writeLoop();
  void drainStderr();
  void setError(const std::string& message);

  std::filesystem::path output_;
  int width_;
  int height_;
  int fps_;
  pid_t pid_ = -1;
  int stdinFd_ = -1;
  int stderrFd_ = -1;
  BoundedQueue<OutputFrame> queue_;
  std::thread writer_;
  std::thread stderrReader_;
  std::string stderrText_;  // written by stderrReader_ only, read after it is joined
  MeanMs writeMs_;
  mutable std::mutex errorMutex_;
  std::string error_;
  bool finished_ = false;
};

}  // namespace rbsim::render
