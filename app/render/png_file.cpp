#include "png_file.h"

#include <csetjmp>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <png.h>

#include "checked_file.h"
#include "render_error.h"

namespace rbsim::render {

namespace {

// libpng's own stdio writer turns a failed fwrite into "Write Error" and loses errno; these
// write through CheckedFile, which keeps the OS's reason for the message.
void writeData(png_structp png, png_bytep data, png_size_t size) {
  if (!static_cast<CheckedFile*>(png_get_io_ptr(png))->write(data, size)) png_error(png, "write failed");
}

void flushData(png_structp) {}  // CheckedFile::close flushes and reports

// libpng prints its errors on stderr by default; keep the words for our own message instead.
void keepError(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void ignoreWarning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp; keep every C++ object with a destructor outside the frame
// that calls setjmp, so none is skipped. Returns false on any libpng error.
bool writeRows(CheckedFile& file, int width, int height, png_bytep* rows, int zlibLevel, std::string& pngError) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &pngError, keepError, ignoreWarning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &file, writeData, flushData);
  png_set_compression_level(png, zlibLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void encodePngFile(const std::filesystem::path& path, int width, int height, const std::uint8_t* rgba,
                   int zlibLevel) {
  if (zlibLevel < kMinPngLevel || zlibLevel > kMaxPngLevel) {
    throw std::invalid_argument("PNG compression level: expected an integer in [0, 9], got " +
                                std::to_string(zlibLevel));
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
  for (std::size_t y = 0; y < rows.size(); ++y) {
    rows[y] = const_cast<png_bytep>(rgba + y * rowBytes);  // libpng's API is not const-correct
  }
  CheckedFile file;
  const bool opened = file.open(path);
  std::string pngError;
  const bool written = opened && writeRows(file, width, height, rows.data(), zlibLevel, pngError);
  const bool closed = opened && file.close();
  if (!written || !closed) {
    // A libpng failure that was not a write (out of memory) leaves no OS reason.
    const std::string why = !file.error().empty() ? file.error()
                            : "libpng: " + (pngError.empty() ? std::string("out of memory") : pngError);
    throw RenderError("could not write PNG " + path.string() + ": " + why);
  }
}

}  // namespace rbsim::render
