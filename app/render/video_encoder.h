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
  // Creates the output's parent folders, checks the file can be written and starts ffmpeg, which
  // writes NAME.partial.EXT beside the output (issue 56, item 7): the video appears whole, when
  // finish() succeeds, or not at all, and a failed run keeps the video of the run before.
  // Throws RenderError if ffmpeg is not on PATH or the path cannot be written (names it).
  VideoEncoder(std::filesystem::path output, int width, int height, int fps,
               std::size_t queueFrames);
  ~VideoEncoder();  // abandons the video unless finish() ran
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  void submit(OutputFrame frame);  // blocks only while the queue is full
  // No more frames: ffmpeg gets end-of-file once the queue has drained and finishes the file on
  // its own; finish() then only waits. No submit() after it.
  void closeInput() { queue_.close(); }
  // Closes ffmpeg's input and waits for it, then renames the finished file into place; throws
  // RenderError with ffmpeg's exit status and its error output when it failed (nothing renamed).
  void finish();
  // Stops ffmpeg and removes the unfinished file: the run failed. Nothing after it.
  void abandon();
  // Empty while all is well; otherwise why frames are being dropped (ffmpeg died early).
  std::string error() const;
  double meanWriteMs() const { return writeMs_.mean(); }

 private:
  void spawn();
  void writeLoop();
  void drainStderr();
  void setError(const std::string& message);

  std::filesystem::path output_;
  std::filesystem::path partial_;  // what ffmpeg writes, renamed to output_ when whole
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
