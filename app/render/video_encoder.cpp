#include "video_encoder.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "png_sequence_writer.h"  // ensureWritableDirectory
#include "ffmpeg_log.h"
#include "render_error.h"

extern char** environ;

namespace rbsim::render {

namespace {

// write() until everything is out; false on any error other than EINTR (EPIPE: ffmpeg exited).
bool writeAll(int fd, const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

VideoEncoder::VideoEncoder(std::filesystem::path output, int width, int height, int fps,
                           std::size_t queueFrames)
    : output_(std::move(output)),
      // The extension stays last: ffmpeg picks the container from it.
      partial_(output_.parent_path() / (output_.stem().string() + ".partial" + output_.extension().string())),
      width_(width), height_(height), fps_(fps), queue_(queueFrames) {
  const std::filesystem::path parent = output_.parent_path();
  ensureWritableDirectory(parent.empty() ? std::filesystem::path(".") : parent);
  std::error_code ec;
  if (std::filesystem::is_directory(output_, ec)) throw RenderError("cannot write video file " + output_.string() + ": " + std::strerror(EISDIR));
  // The existing video is left alone until the new one is whole.
  const int fd = ::open(partial_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw RenderError("cannot write video file " + partial_.string() + ": " + std::strerror(errno));
  ::close(fd);
  spawn();
  writer_ = std::thread([this] { writeLoop(); });
  stderrReader_ = std::thread([this] { drainStderr(); });
}

VideoEncoder::~VideoEncoder() { abandon(); }

void VideoEncoder::abandon() {
  if (finished_) return;
  finished_ = true;
  if (pid_ > 0) ::kill(pid_, SIGKILL);  // its output is thrown away: no need to let it finish
  queue_.close();
  writer_.join();
  stderrReader_.join();
  int status = 0;
  while (pid_ > 0 && waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  std::error_code ec;
  std::filesystem::remove(partial_, ec);
}

void VideoEncoder::spawn() {
  // O_CLOEXEC: ffmpeg must not inherit our ends, or its stdin would never see end-of-file.
  int in[2], err[2];
  if (pipe2(in, O_CLOEXEC) != 0) throw RenderError("pipe() for ffmpeg failed");
  if (pipe2(err, O_CLOEXEC) != 0) {
    close(in[0]);
    close(in[1]);
    throw RenderError("pipe() for ffmpeg failed");
  }
  const std::string size = std::to_string(width_) + "x" + std::to_string(height_);
  const std::string rate = std::to_string(fps_);
  const std::string out = partial_.string();
  std::vector<std::string> args = {"ffmpeg", "-y", "-loglevel", "error", "-f", "rawvideo",
                                   "-pix_fmt", "rgba", "-s", size, "-r", rate, "-i", "-",
                                   "-c:v", "libx264", "-pix_fmt", "yuv420p", "-preset",
                                   "veryfast", "-crf", "20", "-movflags", "+faststart", out};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);  // dup2 clears CLOEXEC
  posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
  // posix_spawnp searches PATH and (glibc >= 2.24) reports a failed exec as its return value.
  const int rc = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(in[0]);
  close(err[1]);
  if (rc != 0) {
    close(in[1]);
    close(err[0]);
    pid_ = -1;
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
    throw RenderError(rc == ENOENT ? std::string("ffmpeg not found on PATH: it is needed to write "
                                                 "the video ") + output_.string() +
                                         " (install the ffmpeg package, or run without a video)"
                                   : "could not start ffmpeg: " + std::string(strerror(rc)));
  }
  stdinFd_ = in[1];
  stderrFd_ = err[0];
}

void VideoEncoder::writeLoop() {
  // If ffmpeg dies, write() raises SIGPIPE, whose default action kills the whole program. Block
  // it in this thread only: write() then fails with EPIPE and the error is reported instead.
  sigset_t pipeSignal;
  sigemptyset(&pipeSignal);
  sigaddset(&pipeSignal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipeSignal, nullptr);
  const std::size_t frameBytes = static_cast<std::size_t>(width_) * height_ * 4;
  bool alive = true;
  while (std::optional<OutputFrame> frame = queue_.pop()) {
    if (!alive) continue;  // keep draining so the producer never blocks on a dead encoder
    const auto start = std::chrono::steady_clock::now();
    alive = frame->rgba->size() == frameBytes &&
            writeAll(stdinFd_, frame->rgba->data(), frameBytes);
    writeMs_.add(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                           start).count());
    if (!alive) {
      setError(frame->rgba->size() != frameBytes
                   ? "frame " + std::to_string(frame->index) + " has the wrong size for the video"
                   : "ffmpeg stopped reading frames (writing " + output_.string() + ")");
      // Consume the SIGPIPE now pending on this thread so it never fires later.
      const timespec zero{0, 0};
      while (sigtimedwait(&pipeSignal, nullptr, &zero) == SIGPIPE) {
      }
    }
  }
  close(stdinFd_);  // end of input: ffmpeg finishes the file and exits
  stdinFd_ = -1;
}

void VideoEncoder::drainStderr() {
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(stderrFd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    appendFfmpegLog(stderrText_, buffer, static_cast<std::size_t>(n));
  }
  close(stderrFd_);
  stderrFd_ = -1;
}

void VideoEncoder::submit(OutputFrame frame) { queue_.push(std::move(frame)); }

void VideoEncoder::setError(const std::string& message) {
  std::lock_guard<std::mutex> lock(errorMutex_);
  if (error_.empty()) error_ = message;
}

std::string VideoEncoder::error() const {
  std::lock_guard<std::mutex> lock(errorMutex_);
  return error_;
}

void VideoEncoder::finish() {
  if (!finished_) {
    finished_ = true;
    queue_.close();
    writer_.join();
    stderrReader_.join();
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    std::string failure;
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
      failure = "ffmpeg exited with status " + std::to_string(WEXITSTATUS(status));
    } else if (WIFSIGNALED(status)) {
      failure = "ffmpeg was killed by signal " + std::to_string(WTERMSIG(status));
    }
    if (!failure.empty()) {
      // The exit status and ffmpeg's own words explain more than a broken pipe: they win.
      std::lock_guard<std::mutex> lock(errorMutex_);
      error_ = failure + " while writing " + output_.string() +
               (stderrText_.empty() ? std::string() : ":\n" + ffmpegLogTail(stderrText_));
    }
    std::error_code ec;
    if (error().empty()) {
      std::filesystem::rename(partial_, output_, ec);
      if (ec) setError("cannot move the finished video " + partial_.string() + " to " + output_.string() + ": " + ec.message());
    }
    if (!error().empty()) std::filesystem::remove(partial_, ec);
  }
  const std::string message = error();
  if (!message.empty()) throw RenderError(message);
}

}  // namespace rbsim::render
