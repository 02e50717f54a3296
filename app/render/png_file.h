#pragma once
// One RGBA8 image to an RGB PNG file: Debian's stb_image_write (the project brief's PNG writer) with
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
// bench_1000_bodies.json (1280x720), CPU per frame and bytes, RGB, no row filter: level 1
// 8.1 ms / 441 kB, 6 16.7 ms / 389 kB, 9 58 ms / 382 kB, 0 7.3 ms / 2.8 MB. Before the frames
// were RGB and the CRC went through libdeflate (RGBA): level 1 10.3 ms / 554 kB, level 0
// 13.1 ms; libpng (RGBA, the rows kept in the CSV) level 1 15.5 ms / 580 kB; stb's own deflate
// 93 ms / 745 kB.
inline constexpr int kDefaultPngLevel = 1;

// PNG row filters (PNG spec 9.2): 0 none, 1 sub, 2 up, 3 average, 4 Paeth. One for every row:
// on the benchmark frame "none" was both the fastest and the smallest at every level (level 1:
// none 8.1 ms / 441 kB, sub 10.0 / 496, Paeth 13.2 / 514, average 10.3 / 559, up 10.3 / 567).
// Rendered frames are flat colour and hard edges, where predicting a pixel from its neighbours
// gains nothing.
inline constexpr int kMinPngRowFilter = 0;
inline constexpr int kMaxPngRowFilter = 4;
inline constexpr int kDefaultPngRowFilter = 0;

// The row filter of every PNG written from now on; process-wide (stb_image_write keeps it in one
// global), so set it only while no frame is being written. For the benchmark.
void setPngRowFilter(int filter);

// Writes `rgba` (width*height*4 bytes, top row first) to `path` as an opaque RGB PNG (the alpha
// bytes are left out). Throws RenderError naming the
// path if it cannot be written, and std::invalid_argument if zlibLevel is outside
// [kMinPngLevel, kMaxPngLevel].
void encodePngFile(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba,
                   int zlibLevel);

}  // namespace rbsim::render
