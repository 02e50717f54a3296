#pragma once
// Joins MP4 files that VideoEncoder wrote with the same size, rate and settings into one, without
// decoding or encoding again: ffmpeg's concat demuxer with stream copy. The reel is its demos'
// videos and its title cards' clips joined this way, so each frame is encoded once, not twice.
#include <filesystem>
#include <vector>

namespace rbsim::render {

// Writes `output` from `parts` in order. Throws RenderError naming the output, with ffmpeg's
// exit status and error output, if ffmpeg is missing or fails. The list ffmpeg reads is written
// beside the output and removed afterwards.
void concatVideos(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output);

}  // namespace rbsim::render
