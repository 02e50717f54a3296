#pragma once
// Writes frames as dir/frame_000000.png ... with stb_image_write and libdeflate (png_file.h) on a small pool of threads (PNG deflate
// is the slowest step of the output path, and frames are independent).
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "bounded_queue.h"
#include "output_frame.h"
#include "timing.h"

namespace rbsim::render {

class PngSequenceWriter {
 public:
  // Creates dir (and parents) and checks that a file can be written there; throws RenderError
  // with the path otherwise, std::invalid_argument for a zlib level outside [0, 9].
  PngSequenceWriter(std::filesystem::path dir, int width, int height, int zlibLevel, int threads,
                    std::size_t queueFrames);
  ~PngSequenceWriter();  // finishes, swallowing errors (call finish() to see them)
  PngSequenceWriter(const PngSequenceWriter&) = delete;
  PngSequenceWriter& operator=(const PngSequenceWriter&) = delete;

  void submit(OutputFrame frame);  // blocks only while the queue is full
  // No more frames: the workers stop once the queue has drained; finish() then only waits.
  void closeInput() { queue_.close(); }
  // Waits for every queued frame; throws RenderError naming the first file that failed.
  void finish();
  // Empty while all is well; otherwise the first file that could not be written.
  std::string error() const;
  double meanWriteMs() const { return writeMs_.mean(); }

 private:
  void work();

  std::filesystem::path dir_;
  int width_;
  int height_;
  int zlibLevel_;
  BoundedQueue<OutputFrame> queue_;
  std::vector<std::thread> workers_;
  MeanMs writeMs_;
  mutable std::mutex errorMutex_;
  std::string error_;
  bool finished_ = false;
};

// Creates `dir` with its parents and proves it writable by creating and removing a probe file.
void ensureWritableDirectory(const std::filesystem::path& dir);

// One PNG (a screenshot), written on the calling thread: RGBA, top row first. Throws RenderError
// naming the path when it cannot be written.
void writePng(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

}  // namespace rbsim::render
