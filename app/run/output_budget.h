#pragma once
// What one run may render and write, checked before the first frame so an absurd request (a typo
// in world.duration, view.fps or view.size) is refused with its estimate instead of filling the
// disk for hours. Writes are checked as they happen as well (checked_file.h); this is the cheap
// early warning.
#include <cstdint>
#include <string>

namespace rbsim::app {

// Frames one video (one run, or the whole `demo all` reel) may have: 4.6 h of video at 60 fps,
// ~5 h of rendering at the ~18 ms a 1280x720 frame costs. More is most likely a typo.
inline constexpr std::uint64_t kMaxRenderedFrames = 1'000'000;  // [frames]
// Bytes of PNG frames one run may write into its --frames folder: more than most disks have free.
inline constexpr double kMaxFramesFolderBytes = 100e9;  // [B]
// PNG size per pixel at --png-level 0: RGBA stored, 4 bytes a pixel (bench/results/png_levels.csv:
// 3693103 B for 1280x720).
inline constexpr double kStoredPngBytesPerPixel = 4.0;  // [B/px]
// At levels 1 to 9 the measured frame took 0.62 to 0.49 bytes a pixel (same file); the lower
// end, so the estimate does not overstate and refuse a run that would fit.
inline constexpr double kDeflatedPngBytesPerPixel = 0.49;  // [B/px]

// Bytes of CSV one --trace may write: more than most disks have free.
inline constexpr double kMaxTraceBytes = 100e9;  // [B]
// A trace row is at least this long: step, time, name and 17 numbers, most of them "0" (a body at
// rest at the origin; a moving one takes ~400). The low end, so the estimate never overstates.
inline constexpr double kMinTraceBytesPerRow = 100.0;  // [B]

// "3.2 GB", "870 MB", "12 kB": a byte count for messages.
std::string formatBytes(double bytes);

// Throws InputError(file, "world.duration", ...) when `frames` exceed kMaxRenderedFrames, and
// InputError(framesDir, "--frames", ...) when PNG frames of width x height at `pngLevel` would
// exceed kMaxFramesFolderBytes (framesDir empty: no PNGs). Each message has the estimate and the
// limit. `what` says where the frames come from ("5 s at view.fps 60").
void checkOutputBudget(const std::string& file, const std::string& what, std::uint64_t frames, int width, int height,
                       int fps, const std::string& framesDir, int pngLevel);

// Throws InputError(tracePath, "--trace", ...) when `rows` trace rows would pass kMaxTraceBytes;
// `how` says where the rows come from ("1e9 steps x 2 bodies").
void checkTraceBudget(const std::string& tracePath, double rows, const std::string& how);

}  // namespace rbsim::app
