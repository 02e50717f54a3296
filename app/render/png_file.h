#pragma once
// One RGBA8 image to a PNG file with libpng, at a chosen zlib level. libpng rather than
// stb_image_write: on a 1280x720 frame of the benchmark scene stb's own deflate took ~53 ms CPU
// at every level it offers (604 kB), zlib at level 1 ~18 ms for a smaller file (567 kB), and the
// level is a per-call argument here instead of a process-wide global.
#include <cstdint>
#include <filesystem>

namespace rbsim::render {

// zlib levels: 0 stores (fastest, ~8x larger), 9 compresses hardest.
inline constexpr int kMinPngLevel = 0;
inline constexpr int kMaxPngLevel = 9;
// build/bench/png_level_bench FRAME bench/results/png_levels.csv, frame 300 of
// bench_1000_bodies.json: level 0 ~5 ms CPU but 3.7 MB, level 1 ~18 ms / 567 kB, level 6 (zlib's
// default) ~49 ms / 460 kB, level 9 ~184 ms / 447 kB. Frames are written for speed; a user who
// wants smaller files passes --png-level.
inline constexpr int kDefaultPngLevel = 1;

// Writes `rgba` (width*height*4 bytes, top row first) to `path` without row filters (rendered
// frames are mostly flat colour, where filters cost time and gained nothing here). Throws
// RenderError naming the path if it cannot be written, and std::invalid_argument if zlibLevel is
// outside [kMinPngLevel, kMaxPngLevel].
void encodePngFile(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba,
                   int zlibLevel);

}  // namespace rbsim::render
