#include "video_concat.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "ffmpeg_log.h"
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
    appendFfmpegLog(errors, buffer, static_cast<std::size_t>(n));
  }
  close(err[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::string ffmetadata(const std::vector<VideoChapter>& chapters) {
  std::string text = ";FFMETADATA1\n";
  for (const VideoChapter& chapter : chapters) {
    text += "[CHAPTER]\nTIMEBASE=1/1000\nSTART=" + std::to_string(chapter.startMs) + "\nEND=" +
            std::to_string(chapter.endMs) + "\ntitle=";
    for (const char c : chapter.title) {
      if (c == '=' || c == ';' || c == '#' || c == '\\' || c == '\n') text += '\\';
      text += c;
    }
    text += "\n";
  }
  return text;
}

void concatVideos(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                  const std::vector<VideoChapter>& chapters) {
  std::filesystem::path list = output, metadata = output;
  list += ".parts.txt";
  metadata += ".chapters.txt";
  const auto write = [](const std::filesystem::path& path, const std::string& text, const char* what) {
    std::ofstream file(path);
    file << text;
    if (!file.flush()) throw RenderError("cannot write " + path.string() + " (" + what + ")");
  };
  std::string listText = "ffconcat version 1.0\n";
  for (const std::filesystem::path& part : parts) listText += "file " + quoted(part) + "\n";
  write(list, listText, "the list of the reel's parts");
  std::vector<std::string> args = {"ffmpeg", "-y", "-loglevel", "error", "-f", "concat", "-safe", "0", "-i", list.string()};
  if (!chapters.empty()) {
    write(metadata, ffmetadata(chapters), "the reel's chapters for ffmpeg");
    // Input 1 has no streams, only chapters: the video is input 0's, the chapters input 1's
    // (-map_chapters takes them from there instead of from the first input, ffmpeg(1)).
    args.insert(args.end(), {"-f", "ffmetadata", "-i", metadata.string(), "-map", "0", "-map_chapters", "1"});
  }
  // Written beside its name and renamed when whole, as every video (VideoEncoder): a failed join
  // keeps the reel there was. The extension stays last: ffmpeg picks the container from it.
  const std::filesystem::path partial = output.parent_path() / (output.stem().string() + ".partial" + output.extension().string());
  args.insert(args.end(), {"-c", "copy", "-movflags", "+faststart", partial.string()});
  std::string errors;
  const int status = runFfmpeg(args, errors);
  std::error_code ignored;
  std::filesystem::remove(list, ignored);
  std::filesystem::remove(metadata, ignored);
  if (status != 0) {
    std::filesystem::remove(partial, ignored);
    throw RenderError("ffmpeg could not join " + std::to_string(parts.size()) + " videos into " + output.string() +
                      " (exit status " + std::to_string(status) + "): " + ffmpegLogTail(errors));
  }
  std::error_code moved;
  std::filesystem::rename(partial, output, moved);
  if (moved) {
    std::filesystem::remove(partial, ignored);
    throw RenderError("cannot move the joined reel " + partial.string() + " to " + output.string() + ": " + moved.message());
  }
}

}  // namespace rbsim::render
