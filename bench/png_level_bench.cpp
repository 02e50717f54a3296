// PNG encode cost (issues 11 and 22): one rendered frame encoded by the frame writers' encoder
// (stb_image_write with libdeflate, render/png_file.h) at every level and row filter, and by
// Debian's libstb as it comes (stb's own deflate at its default level 8, its per-row filter
// search), CPU ms of the calling thread (median of 5) and bytes. Each file is read back and
// must hold the exact pixels. Usage: png_level_bench FRAME.png OUT.csv (e.g. a 1280x720 frame
// of the benchmark scene).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <stb/stb_image.h>        // implementations in Debian's libstb, linked via rbsim_render
#include <stb/stb_image_write.h>

#include "render/png_file.h"

namespace {

constexpr int kRepeats = 5;

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// Median CPU ms of `encode` writing `out`; false if the file does not decode to the colours of
// `pixels` (RGB: the frame writers store opaque frames, png_file.h).
bool measure(const std::function<void()>& encode, const std::filesystem::path& out, const unsigned char* pixels,
             int width, int height, double& ms, std::uintmax_t& bytes) {
  std::vector<double> runs;
  for (int k = 0; k < kRepeats; ++k) {
    const double start = threadCpuMs();
    encode();
    runs.push_back(threadCpuMs() - start);
  }
  std::nth_element(runs.begin(), runs.begin() + kRepeats / 2, runs.end());
  ms = runs[kRepeats / 2];
  bytes = std::filesystem::file_size(out);
  int w = 0, h = 0, channels = 0;
  unsigned char* back = stbi_load(out.string().c_str(), &w, &h, &channels, 4);
  bool same = back != nullptr && w == width && h == height;
  for (std::size_t i = 0; same && i < static_cast<std::size_t>(width) * height * 4; ++i) {
    same = i % 4 == 3 || back[i] == pixels[i];
  }
  stbi_image_free(back);
  return same;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s FRAME.png OUT.csv\n", argv[0]);
    return 2;
  }
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(argv[1], &width, &height, &channels, 4);
  if (pixels == nullptr) {
    std::fprintf(stderr, "cannot read %s\n", argv[1]);
    return 2;
  }
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "rbsim_png_level_bench.png";
  std::ofstream csv(argv[2]);
  csv << "writer,filter,level,width,height,encode_cpu_ms,bytes\n";
  bool allSame = true;
  const auto row = [&](const char* writer, int filter, int level, const std::function<void()>& encode) {
    double ms = 0.0;
    std::uintmax_t bytes = 0;
    const bool same = measure(encode, out, pixels, width, height, ms, bytes);
    allSame = allSame && same;
    csv << writer << ',' << filter << ',' << level << ',' << width << ',' << height << ',' << ms << ',' << bytes << '\n';
    std::printf("%-14s filter %2d level %d: %6.1f ms CPU, %9ju bytes%s\n", writer, filter, level, ms,
                static_cast<std::uintmax_t>(bytes), same ? "" : "  PIXELS DIFFER");
  };
  for (int filter = rbsim::render::kMinPngRowFilter; filter <= rbsim::render::kMaxPngRowFilter; ++filter) {
    rbsim::render::setPngRowFilter(filter);
    for (int level = rbsim::render::kMinPngLevel; level <= rbsim::render::kMaxPngLevel; ++level) {
      row("stb+libdeflate", filter, level, [&] { rbsim::render::encodePngFile(out, width, height, pixels, level); });
    }
  }
  // Debian's libstb as shipped: stb's deflate at its default level, filters searched per row (-1).
  row("stb", -1, 8, [&] { stbi_write_png(out.string().c_str(), width, height, 4, pixels, width * 4); });
  std::filesystem::remove(out);
  stbi_image_free(pixels);
  if (!allSame) std::fprintf(stderr, "png_level_bench: a file did not decode to the frame's pixels\n");
  return allSame ? 0 : 1;
}
