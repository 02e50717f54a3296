// PNG encode cost per zlib level (issue 11): one rendered frame encoded with encodePngFile (the
// frame writers' encoder) at levels 0 to 9, CPU ms of the calling thread (median of 5) and file
// size. Usage: png_level_bench FRAME.png OUT.csv (e.g. a 1280x720 frame of the benchmark scene).
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <vector>

#include <stb/stb_image.h>  // implementation in Debian's libstb, linked via rbsim_render

#include "render/png_file.h"

namespace {

constexpr int kRepeats = 5;

double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
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
  csv << "level,width,height,encode_cpu_ms,bytes\n";
  for (int level = rbsim::render::kMinPngLevel; level <= rbsim::render::kMaxPngLevel; ++level) {
    std::vector<double> ms;
    for (int k = 0; k < kRepeats; ++k) {
      const double start = threadCpuMs();
      rbsim::render::encodePngFile(out, width, height, pixels, level);
      ms.push_back(threadCpuMs() - start);
    }
    std::nth_element(ms.begin(), ms.begin() + kRepeats / 2, ms.end());
    const auto bytes = std::filesystem::file_size(out);
    csv << level << ',' << width << ',' << height << ',' << ms[kRepeats / 2] << ',' << bytes << '\n';
    std::printf("level %d: %.1f ms CPU, %ju bytes\n", level, ms[kRepeats / 2], static_cast<std::uintmax_t>(bytes));
  }
  std::filesystem::remove(out);
  stbi_image_free(pixels);
  return 0;
}
