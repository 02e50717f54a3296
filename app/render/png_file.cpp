#include "png_file.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <libdeflate.h>

#include "checked_file.h"
#include "render_error.h"

namespace rbsim::render {

namespace {

// stb_image_write hands its compressor one process-wide level; ours comes with each call, so the
// writer threads may each write at their own.
thread_local int threadLevel = kDefaultPngLevel;

// A libdeflate compressor per thread, kept for the next frame at the same level: allocating one
// (its hash tables) costs about as much as compressing a small frame.
struct ThreadCompressor {
  int level = -1;
  libdeflate_compressor* compressor = nullptr;
  ~ThreadCompressor() { libdeflate_free_compressor(compressor); }
  libdeflate_compressor* at(int wanted) {
    if (wanted != level) {
      libdeflate_free_compressor(compressor);
      compressor = libdeflate_alloc_compressor(wanted);
      level = compressor != nullptr ? wanted : -1;
    }
    return compressor;
  }
};
thread_local ThreadCompressor threadCompressor;

}  // namespace

// stb_image_write's STBIW_ZLIB_COMPRESS hook: the zlib stream of the filtered rows, in memory stb
// releases with free(); nullptr (stb then fails the write) if it cannot be made.
unsigned char* zlibForStb(const unsigned char* data, int length, int* outLength, int /*stbLevel*/) {
  libdeflate_compressor* compressor = threadCompressor.at(threadLevel);
  if (compressor == nullptr || length < 0) return nullptr;
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, static_cast<std::size_t>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  if (out == nullptr) return nullptr;
  const std::size_t written = libdeflate_zlib_compress(compressor, data, static_cast<std::size_t>(length), out, bound);
  if (written == 0 || written > static_cast<std::size_t>(INT32_MAX)) {
    std::free(out);
    return nullptr;
  }
  *outLength = static_cast<int>(written);
  return out;
}

}  // namespace rbsim::render

// Debian's stb_image_write (libstb-dev), compiled here with libdeflate behind its deflate hook and
// kept static so it never meets libstb's own copy of the same functions.
#define STBIW_ZLIB_COMPRESS(data, length, outLength, level) rbsim::render::zlibForStb(data, length, outLength, level)
// The chunks' CRC-32 through libdeflate too: stb's own goes a byte at a time through a table, and
// over a stored (level 0) frame of 3.7 MB it cost more than the rest of the write.
#define STBIW_CRC32(buffer, length) \
  static_cast<unsigned int>(libdeflate_crc32(0, buffer, static_cast<std::size_t>(length)))
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace rbsim::render {

namespace {

void writeToFile(void* context, void* data, int size) {
  static_cast<CheckedFile*>(context)->write(data, static_cast<std::size_t>(size));  // keeps its failure
}

// stb's forced row filter is one process-wide global, set here at start-up and by
// setPngRowFilter; never by a writer thread.
const bool kRowFilterSet = (stbi_write_force_png_filter = kDefaultPngRowFilter, true);

}  // namespace

void setPngRowFilter(int filter) {
  if (filter < kMinPngRowFilter || filter > kMaxPngRowFilter) {
    throw std::invalid_argument("PNG row filter: expected an integer in [0, 4], got " + std::to_string(filter));
  }
  stbi_write_force_png_filter = filter;
}

void encodePngFile(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba,
                   int zlibLevel) {
  if (zlibLevel < kMinPngLevel || zlibLevel > kMaxPngLevel) {
    throw std::invalid_argument("PNG compression level: expected an integer in [0, 9], got " +
                                std::to_string(zlibLevel));
  }
  threadLevel = zlibLevel;
  // Opaque RGB: a frame is a picture, and GL's alpha after blending is bookkeeping (an outline's
  // antialiased edge leaves 0.8 there), which a viewer would show as holes. A quarter fewer bytes
  // to filter and deflate, too.
  thread_local std::vector<std::uint8_t> rgb;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  rgb.resize(pixels * 3);
  for (std::size_t k = 0; k < pixels; ++k) {
    rgb[3 * k] = rgba[4 * k];
    rgb[3 * k + 1] = rgba[4 * k + 1];
    rgb[3 * k + 2] = rgba[4 * k + 2];
  }
  CheckedFile file;
  const bool opened = file.open(path);
  const bool written = opened && stbi_write_png_to_func(writeToFile, &file, width, height, 3, rgb.data(), width * 3) != 0;
  const bool closed = opened && file.close();
  if (!written || !closed) {
    // A failure that was not a write (the compressor out of memory) leaves no OS reason.
    const std::string why = !file.error().empty() ? file.error() : std::string("out of memory compressing it");
    throw RenderError("could not write PNG " + path.string() + ": " + why);
  }
}

}  // namespace rbsim::render
