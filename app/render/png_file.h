#pragma once
// One RGBA8 image to a PNG file: Debian's stb_image_write (the project brief's PNG writer) with
// libdeflate behind its deflate hook (STBIW_ZLIB_COMPRESS) and one forced row filter. stb's own
// deflate and its per-row filter search were what made it slow (~53 ms a 1280x720 frame at every
// level), not the format. The level is per call: each writer thread may write at its own.
#include <cstdint>
#include <filesystem>

namespace rbsim::render {

// Levels on zlib's scale: 0 stores (fastest, largest), 9 compresses hardest (libdeflate's
// levels 0 to 9 of its 0 to 12).
inline constexpr int kMinPngLevel = 0;
inline constexpr int kMaxPngLevel = 9;
// Frames are written for speed; a user who wants smaller files passes --png-level.
// build/bench/png_level_bench FRAME bench/results/png_levels.csv on frame 300 of
// bench_1000_bodies.json (1280x720), CPU per frame and bytes, no row filter: level 1 10.3 ms /
// 554 kB, 6 24.5 ms / 482 kB, 9 89 ms / 463 kB, 0 13.1 ms / 3.7 MB (stb's CRC and copies of the
// stored rows: libpng stored it in 4.1 ms). libpng at level 1 took 15.5 ms / 580 kB, stb's own
// deflate 91 ms / 745 kB.
inline constexpr int kDefaultPngLevel = 1;

// PNG row filters (PNG spec 9.2): 0 none, 1 sub, 2 up, 3 average, 4 Paeth. One for every row:
// on the benchmark frame "none" was both the fastest and the smallest at every level (level 1:
// none 10.3 ms / 554 kB, sub 14.0 / 618, Paeth 18.1 / 640, up 14.0 / 695, average 14.4 / 702).
// Rendered frames are flat colour and hard edges, where predicting a pixel from its neighbours
// gains nothing.
inline constexpr int kMinPngRowFilter = 0;
inline constexpr int kMaxPngRowFilter = 4;
inline constexpr int kDefaultPngRowFilter = 0;

// The row filter of every PNG written from now on; process-wide (stb_image_write keeps it in one
// global), so set it only while no frame is being written. For the benchmark.
void setPngRowFilter(int filter);

// Writes `rgba` (width*height*4 bytes, top row first) to `path`. Throws RenderError naming the
// path if it cannot be written, and std::invalid_argument if zlibLevel is outside
// [kMinPngLevel, kMaxPngLevel].
void encodePngFile(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba,
                   int zlibLevel);

}  // namespace rbsim::render
