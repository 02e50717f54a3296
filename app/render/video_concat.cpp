#include "video_concat.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "render_error.h"

extern char** environ;

namespace rbsim::render {

namespace {

// A path as the concat demuxer's `file` directive reads it: single-quoted, with each ' written
// as '\'' (ffmpeg-formats(1), "concat").
std::string quoted(const std::filesystem::path& path) {
  std::string out = "'";
  for (const char c : std::filesystem::absolute(path).string()) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

// Runs ffmpeg with `args` and waits; returns its exit status (-1: killed) and its error output.
int runFfmpeg(std::vector<std::string> args, std::string& errors) {
  int err[2];
  if (pipe2(err, O_CLOEXEC) != 0) throw RenderError("pipe() for ffmpeg failed");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(err[1]);
  if (rc != 0) {
    close(err[0]);
    throw RenderError(rc == ENOENT ? std::string("ffmpeg not found on PATH (install the ffmpeg package)")
                                   : "could not start ffmpeg: " + std::string(std::strerror(rc)));
  }
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(err[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (errors.size() < 65536) errors.append(buffer, static_cast<std::size_t>(n));
  }
  close(err[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

void concatVideos(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output) {
  std::filesystem::path list = output;
  list += ".parts.txt";
  {
    std::ofstream file(list);
    file << "ffconcat version 1.0\n";
    for (const std::filesystem::path& part : parts) file << "file " << quoted(part) << "\n";
    if (!file.flush()) throw RenderError("cannot write " + list.string() + " (the list of the reel's parts)");
  }
  std::string errors;
  const int status = runFfmpeg({"ffmpeg", "-y", "-loglevel", "error", "-f", "concat", "-safe", "0", "-i",
                                list.string(), "-c", "copy", "-movflags", "+faststart", output.string()},
                               errors);
  std::error_code ignored;
  std::filesystem::remove(list, ignored);
  if (status != 0) {
    while (!errors.empty() && (errors.back() == '\n' || errors.back() == ' ')) errors.pop_back();
    throw RenderError("ffmpeg could not join " + std::to_string(parts.size()) + " videos into " + output.string() +
                      " (exit status " + std::to_string(status) + "): " + errors);
  }
}

}  // namespace rbsim::render
