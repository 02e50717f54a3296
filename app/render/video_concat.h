#pragma once
// Joins MP4 files that VideoEncoder wrote with the same size, rate and settings into one, without
// decoding or encoding again: ffmpeg's concat demuxer with stream copy. The reel is its demos'
// videos and its title cards' clips joined this way, so each frame is encoded once, not twice.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rbsim::render {

// A chapter of the joined video, in milliseconds from its start (the MP4 muxer's chapter clock:
// TIMEBASE=1/1000 in ffmpeg's FFMETADATA1 file).
struct VideoChapter {
  std::int64_t startMs = 0;
  std::int64_t endMs = 0;
  std::string title;
};

// The FFMETADATA1 text ffmpeg reads the chapters from (ffmpeg-formats(1), "Metadata"): one
// [CHAPTER] section each, with '=', ';', '#', backslash and line break in a title escaped by a backslash.
std::string ffmetadata(const std::vector<VideoChapter>& chapters);

// Writes `output` from `parts` in order, with `chapters` (if any) as the MP4's chapter list
// (still a stream copy: the chapters are muxed, nothing is encoded again). Throws RenderError
// naming the output, with ffmpeg's exit status and error output, if ffmpeg is missing or fails. The list ffmpeg reads (and the
// chapters' metadata file) is written beside the output and removed afterwards.
void concatVideos(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                  const std::vector<VideoChapter>& chapters = {});

}  // namespace rbsim::render
