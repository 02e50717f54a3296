#pragma once
// One RGBA8 image to a PNG file with libpng, at a chosen zlib level. libpng rather than
// stb_image_write: stb's own deflate took ~43 ms for a 1280x720 frame at every level it offers,
// zlib at level 1 ~15 ms for a smaller file (bench/results/png_levels.csv), and the level is a
// per-call argument here instead of a process-wide global.
#include <cstdint>
#include <filesystem>

namespace rbsim::render {

// zlib levels: 0 stores (fastest, ~8x larger), 9 compresses hardest.
inline constexpr int kMinPngLevel = 0;
inline constexpr int kMaxPngLevel = 9;
// Measured on a 1280x720 frame of demo 5: level 1 encoded in ~15 ms CPU into 434 kB, level 6
// (zlib's default) in ~33 ms into 354 kB, level 9 in ~125 ms into 343 kB. Frames are written
// for speed; a user who wants smaller files passes --png-level.
inline constexpr int kDefaultPngLevel = 1;

// Writes `rgba` (width*height*4 bytes, top row first) to `path` without row filters (rendered
// frames are mostly flat colour, where filters cost time and gained nothing here). Throws
// RenderError naming the path if it cannot be written, and std::invalid_argument if zlibLevel is
// outside [kMinPngLevel, kMaxPngLevel].
void encodePngFile(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba,
                   int zlibLevel);

}  // namespace rbsim::render
