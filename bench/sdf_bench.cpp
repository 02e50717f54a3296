// Signed distance grids (issue 9, seed 000 "Constructing Signed Distance Functions", "Fast
// Marching Method"): build time against resolution for a sphere and a torus mesh, with the grid
// point count N so fast marching's O(N log N) shows as a flat ns per N log2 N; accuracy against
// resolution (max and RMS |phi_grid - phi_exact| at random points within 0.1 m of the surface of
// a unit sphere or of the torus (R 1 m, r 0.3 m), in metres and in cells); and the cost of one
// phi() + gradient() query. Times are processor time (the machine is shared): build_ms and its
// phases from build()'s stats (exact band incl. the BVH build, marching over its M points, sign). With fine meshes the exact band and the BVH dominate small grids, so the marching phase
// is reported per M log2 M on its own.
// Meshes are fine (sphere 256 x 128, torus 256 x 96) so their faceting, not the grid, is < 0.03 cell.
//   usage: sdf_bench                       Google Benchmark: build and query timings
//          sdf_bench --csv bench/results/sdf.csv    the table on stdout and as CSV (about 2 min)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "geometry/implicit_surface.h"
#include "rbsim/geometry/mesh_generators.h"
#include "rbsim/geometry/signed_distance_grid.h"

namespace {

using namespace rbsim;

constexpr double kTorusMajor = 1.0;       // [m]
constexpr double kTorusMinor = 0.3;       // [m]
constexpr double kNearSurface = 0.1;      // [m] accuracy sample band around the surface
constexpr int kAccuracySamples = 200000;  // random points in the band
constexpr int kQueries = 1000000;         // phi() + gradient() calls timed
constexpr unsigned kSeed = 9;
const int kResolutions[] = {16, 32, 64, 128};

struct Shape {
  std::string name;
  Mesh mesh;
  std::function<double(const Vec3&)> exact;  // analytic signed distance [m]
  double halfBox;                            // sample cube half side [m]
};

std::vector<Shape> shapes() {
  const SphereSurface sphere{1.0};
  return {{"sphere", makeUvSphere(1.0, 256, 128), [sphere](const Vec3& p) { return sphere.phi(p); }, 1.2},
          {"torus", makeTorus(kTorusMajor, kTorusMinor, 256, 96),
           [](const Vec3& p) {
             return std::hypot(std::hypot(p.x(), p.z()) - kTorusMajor, p.y()) - kTorusMinor;
           },
           kTorusMajor + kTorusMinor + kNearSurface}};
}

double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

std::vector<Vec3> pointsNearSurface(const Shape& shape, int count) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-shape.halfBox, shape.halfBox);
  std::vector<Vec3> points;
  while (static_cast<int>(points.size()) < count) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (std::abs(shape.exact(p)) <= kNearSurface) points.push_back(p);
  }
  return points;
}

// Nanoseconds per phi() + gradient() at random points of the grid's box.
double queryNs(const SignedDistanceGrid& grid) {
  std::mt19937 rng(kSeed);
  const Vec3 size = grid.cellSize() * (grid.dims() - Vec3i::Ones()).cast<double>();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points(kQueries);
  for (Vec3& p : points) p = grid.origin() + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(size);
  double sink = 0.0;
  const double start = threadSeconds();
  for (const Vec3& p : points) sink += grid.phi(p) + grid.gradient(p).x();
  const double seconds = threadSeconds() - start;
  benchmark::DoNotOptimize(sink);
  return 1e9 * seconds / kQueries;
}

int writeCsv(const char* path) {
  std::FILE* csv = std::fopen(path, "w");
  if (csv == nullptr) {
    std::fprintf(stderr, "sdf_bench: cannot write %s\n", path);
    return 2;
  }
  std::fprintf(csv, "shape,resolution,points,exact_points,marched_points,regions,build_ms,exact_ms,"
                    "march_ms,sign_ms,ns_per_NlogN,march_ns_per_MlogM,cell_m,max_err_m,rms_err_m,"
                    "max_err_cells,rms_err_cells,query_ns\n");
  std::printf("%-6s %4s %8s %8s %8s %8s %8s %8s %8s %9s %7s %9s %9s %6s %6s %6s\n", "shape", "res",
              "points", "exact", "build_ms", "exact_ms", "march_ms", "sign_ms", "ns/NlgN",
              "march/MlgM", "h_m", "max_err_m", "rms_err_m", "max_h", "rms_h", "q_ns");
  for (const Shape& shape : shapes()) {
    const std::vector<Vec3> samples = pointsNearSurface(shape, kAccuracySamples);
    for (int resolution : kResolutions) {
      const SignedDistanceGrid grid = SignedDistanceGrid::build(shape.mesh, {resolution, 3, 2});
      const double buildSeconds = grid.stats().seconds;
      const double n = static_cast<double>(grid.pointCount());
      double maxErr = 0.0, sumSq = 0.0;
      for (const Vec3& p : samples) {
        const double e = std::abs(grid.phi(p) - shape.exact(p));
        maxErr = std::max(maxErr, e);
        sumSq += e * e;
      }
      const double rms = std::sqrt(sumSq / samples.size());
      const double h = grid.cellSize();
      const double ns = queryNs(grid);
      const double perNlogN = 1e9 * buildSeconds / (n * std::log2(n));
      const SignedDistanceGrid::BuildStats& s = grid.stats();
      const double m = static_cast<double>(s.marchedPoints);
      const double marchPerMlogM = 1e9 * s.marchSeconds / (m * std::log2(m));
      std::fprintf(csv, "%s,%d,%zu,%zu,%zu,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.6f,%.6e,%.6e,%.4f,%.4f,%.1f\n",
                   shape.name.c_str(), resolution, grid.pointCount(), s.exactPoints, s.marchedPoints,
                   s.regions, 1e3 * buildSeconds, 1e3 * s.exactSeconds, 1e3 * s.marchSeconds,
                   1e3 * s.signSeconds, perNlogN, marchPerMlogM, h, maxErr, rms, maxErr / h, rms / h, ns);
      std::printf("%-6s %4d %8zu %8zu %8.1f %8.1f %8.1f %8.1f %8.1f %9.1f %7.4f %9.2e %9.2e %6.3f %6.3f %6.1f\n",
                  shape.name.c_str(), resolution, grid.pointCount(), s.exactPoints, 1e3 * buildSeconds,
                  1e3 * s.exactSeconds, 1e3 * s.marchSeconds, 1e3 * s.signSeconds, perNlogN,
                  marchPerMlogM, h, maxErr, rms, maxErr / h, rms / h, ns);
      std::fflush(stdout);
    }
  }
  std::fclose(csv);
  return 0;
}

void BM_Build(benchmark::State& state, int shapeIndex) {
  const Shape shape = shapes()[shapeIndex];
  const int resolution = static_cast<int>(state.range(0));
  std::size_t points = 0;
  for (auto _ : state) {
    const SignedDistanceGrid grid = SignedDistanceGrid::build(shape.mesh, {resolution, 3, 2});
    points = grid.pointCount();
    benchmark::DoNotOptimize(grid.value(0, 0, 0));
  }
  const double n = static_cast<double>(points);
  state.counters["points"] = n;
  state.counters["ns_per_NlogN"] = benchmark::Counter(
      n * std::log2(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_Build, sphere, 0)->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_Build, torus, 1)->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_PhiAndGradient(benchmark::State& state) {
  const SignedDistanceGrid grid =
      SignedDistanceGrid::build(shapes()[0].mesh, {static_cast<int>(state.range(0)), 3, 2});
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::vector<Vec3> points(4096);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  std::size_t i = 0;
  for (auto _ : state) {
    const Vec3& p = points[i++ & 4095];
    benchmark::DoNotOptimize(grid.phi(p));
    benchmark::DoNotOptimize(grid.gradient(p));
  }
}
BENCHMARK(BM_PhiAndGradient)->Arg(32)->Arg(128);

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--csv") == 0) return writeCsv(argv[2]);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
