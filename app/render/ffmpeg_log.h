#pragma once
// What ffmpeg wrote on stderr, kept for the message when it fails: the last kFfmpegLogBytes, since
// its reason comes last (a long run of warnings before it would push it out of a kept head).
#include <cstddef>
#include <string>

namespace rbsim::render {

inline constexpr std::size_t kFfmpegLogBytes = 16384;  // [bytes]
// Lines of it a message quotes at most.
inline constexpr int kFfmpegLogLines = 12;

inline void appendFfmpegLog(std::string& log, const char* data, std::size_t bytes) {
  log.append(data, bytes);
  if (log.size() > kFfmpegLogBytes) log.erase(0, log.size() - kFfmpegLogBytes);
}

// The last kFfmpegLogLines lines of the log, without trailing blanks; "" for an empty log.
inline std::string ffmpegLogTail(std::string log) {
  while (!log.empty() && (log.back() == '\n' || log.back() == '\r' || log.back() == ' ')) log.pop_back();
  std::size_t start = log.size();
  for (int lines = 0; lines < kFfmpegLogLines; ++lines) {
    const std::size_t newline = start == 0 ? std::string::npos : log.rfind('\n', start - 1);
    if (newline == std::string::npos) return log;  // fewer lines than that: all of it
    start = newline;
  }
  return log.substr(start + 1);
}

}  // namespace rbsim::render
