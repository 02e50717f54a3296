// Particle systems (issue 6): particle-steps per second for 1e3, 1e5 and 1e6 particles under
// gravity, linear and quadratic drag and a ground plane, against the memory-bandwidth bound
// bandwidth / (bytes per particle-step); and frames per second of drawing 1e5 sprites at
// 1280x720 (additive and alpha-blended), with the app's sprite building timed apart.
// Run: build/bench/particle_bench --benchmark_repetitions=3 --benchmark_min_time=1
// The console output ends with a summary of the bound.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rbsim/math/uniform_random.h"
#include "render/offscreen_renderer.h"
#include "run/particle_view.h"
#include "memory_bound.h"
#include "rbsim/world/world.h"
#include "rbsim/world/systems.h"

namespace {

using namespace rbsim;
using namespace rbsim::bench;

constexpr int kParticleCounts[] = {1000, 100000, 1000000};
constexpr int kOutOfCacheParticles = 1000000;  // the count the bound is stated for
constexpr int kSpriteCount = 100000;
constexpr int kImageWidth = 1280, kImageHeight = 720;  // [px]
constexpr std::uint64_t kSeed = 20261122;
constexpr double kHalfSpread = 5.0;  // [m] particles fill [-5, 5] x [0, 10] x [-5, 5]
constexpr double kMaxSpeed = 5.0;    // [m/s] per component

// Bytes the step's single pass reads and writes per particle (particle_system.cpp, substep):
// each attribute once, a read-and-rewritten one twice, as memcpy's source and destination count.
// Colour and size are never touched by the step: that is what the structure of arrays buys.
// Every 16th step also reads the velocities once more (the divergence check, 1.5 B per
// particle-step on average), left out of the count, as the bound errs on the strict side.
struct FieldTraffic {
  const char* field;
  std::size_t readBytes;
  std::size_t writtenBytes;
};
const FieldTraffic kEveryStep[] = {
    {"position x", sizeof(Vec3), sizeof(Vec3)},
    {"velocity v", sizeof(Vec3), sizeof(Vec3)},
    {"inverse mass", sizeof(double), 0},
    {"age", sizeof(double), sizeof(double)},
    {"lifetime", sizeof(double), 0},
};
// Every attribute a particle stores (particle_store.h), the state bytes per particle.
constexpr std::size_t kStateBytes = 2 * sizeof(Vec3) + 3 * sizeof(double) + sizeof(Eigen::Vector3f) + sizeof(float);

std::size_t bytesPerParticleStep() {
  std::size_t total = 0;
  for (const FieldTraffic& f : kEveryStep) total += f.readBytes + f.writtenBytes;
  return total;
}

// `count` immortal particles of 1 to 10 g at random places and velocities, gravity, drag and a
// ground plane: every particle is stepped and tested against the plane every step.
World particleWorld(int count) {
  Settings settings;
  World world(settings);
  world.addPlane(Plane{});
  ParticleSystemDef def;
  def.capacity = static_cast<std::size_t>(count);
  def.dragLinear = 1e-4;
  def.dragQuadratic = 1e-5;
  def.collision.restitution = 0.5;
  addParticleSystem(world, def);
  ParticleStore& p = particleSystems(world)[0].particles();
  UniformRandom random(kSeed);
  for (int i = 0; i < count; ++i) {
    const std::size_t k = p.add();
    p.position[k] = Vec3(random.between(-kHalfSpread, kHalfSpread), random.between(0.0, 2.0 * kHalfSpread),
                         random.between(-kHalfSpread, kHalfSpread));
    p.velocity[k] = kMaxSpeed * Vec3(random.between(-1.0, 1.0), random.between(-1.0, 1.0), random.between(-1.0, 1.0));
    p.inverseMass[k] = 1.0 / random.between(0.001, 0.01);
    p.lifetime[k] = kImmortal;
    p.size[k] = 0.05f;
  }
  return world;
}

// Every run measures the same regime: a cloud's first kStepsPerCloud steps, most particles in
// flight and some meeting the ground (left alone, the cloud settles on the plane and every
// particle collides every step, so runs of different lengths would measure different work).
constexpr int kStepsPerCloud = 60;  // 0.25 s at the default 240 steps/s

void stepParticles(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  World world = particleWorld(count);
  int steps = 0;
  for (auto _ : state) {
    if (++steps == kStepsPerCloud) {
      state.PauseTiming();
      world = particleWorld(count);
      steps = 0;
      state.ResumeTiming();
    }
    world.step();
    benchmark::DoNotOptimize(particleSystems(world)[0].particles().position.back());
  }
  state.SetItemsProcessed(state.iterations() * count);
  state.counters["bytes_per_particle_step"] = static_cast<double>(bytesPerParticleStep());
  state.counters["state_bytes_per_particle"] = static_cast<double>(kStateBytes);
}



// A fountain-sized cloud of 1e5 particles in front of the default camera, as the app draws it.
struct SpriteScene {
  World world = particleWorld(kSpriteCount);
  Scene scene;
  explicit SpriteScene(ParticleLook::Blend blend) {
    scene.view.eye = Vec3(8.0, 6.0, 14.0);
    scene.view.target = Vec3(0.0, 4.0, 0.0);
    ParticleLook look;
    look.blend = blend;
    look.alphaStart = look.alphaEnd = 0.5;
    scene.particleLooks.push_back(look);
  }
  render::FrameData frame() const {
    render::FrameData f;
    f.camera.eye = glm::vec3(8.0f, 6.0f, 14.0f);
    f.camera.target = glm::vec3(0.0f, 4.0f, 0.0f);
    f.options.overlay = false;
    app::addParticleView(world, scene, f);
    return f;
  }
};

render::OffscreenRenderer& renderer() {
  static render::OffscreenRenderer instance(kImageWidth, kImageHeight);
  return instance;
}

// Building the sprites from the World (age ramps; alpha batches sorted back to front).
void buildSprites(benchmark::State& state, ParticleLook::Blend blend) {
  const SpriteScene sprites(blend);
  for (auto _ : state) benchmark::DoNotOptimize(sprites.frame());
  state.SetItemsProcessed(state.iterations() * kSpriteCount);
}

// Drawing them at 1280x720 and reading the image back; items = frames.
void renderSprites(benchmark::State& state, ParticleLook::Blend blend) {
  const SpriteScene sprites(blend);
  const render::FrameData frame = sprites.frame();
  for (auto _ : state) benchmark::DoNotOptimize(renderer().render(frame).data());
  state.SetItemsProcessed(state.iterations());
  state.counters["sprites"] = static_cast<double>(frame.sprites.at(0).sprites.size());
}

// The same frame without its sprites: what the sky, the ground and the read-back cost alone.
void renderNoSprites(benchmark::State& state) {
  render::FrameData frame = SpriteScene(ParticleLook::Blend::Additive).frame();
  frame.sprites.clear();
  for (auto _ : state) benchmark::DoNotOptimize(renderer().render(frame).data());
  state.SetItemsProcessed(state.iterations());
}

void printSummary(const SummaryReporter& results) {
  std::printf("\nBytes read + written per particle-step (particle_system.cpp, one pass):\n");
  for (const FieldTraffic& f : kEveryStep) std::printf("  %-14s read %3zu  written %3zu\n", f.field, f.readBytes, f.writtenBytes);
  const double bytes = static_cast<double>(bytesPerParticleStep());
  std::printf("  total %.0f B per particle-step; state %zu B per particle (with colour and size)\n", bytes, kStateBytes);
  const double bandwidth = results.rate(copyBenchmarkName(outOfCacheBytes()));
  const double measured = results.rate("step/" + std::to_string(kOutOfCacheParticles));
  if (bandwidth > 0.0 && measured > 0.0) {
    std::printf("\nAt %d particles: memcpy %.2f GB/s -> bound %.4g particle-steps/s; measured %.4g; bound/x = %.2f\n",
                kOutOfCacheParticles, bandwidth / 1e9, bandwidth / bytes, measured, bandwidth / bytes / measured);
  }
  const double empty = results.rate("render_no_sprites/real_time");
  if (empty > 0.0) std::printf("the same frame without sprites: %.1f frames/s\n", empty);
  for (const char* blend : {"additive", "alpha"}) {
    const double fps = results.rate(std::string("render_1e5_sprites/") + blend + "/real_time");
    if (fps > 0.0) std::printf("1e5 %s sprites at %dx%d: %.1f frames/s (draw and read back)\n", blend, kImageWidth, kImageHeight, fps);
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (int count : kParticleCounts) {
    benchmark::RegisterBenchmark("step", stepParticles)->Arg(count)->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("memcpy", copyBuffer)->Arg(static_cast<std::int64_t>(outOfCacheBytes()))->Unit(benchmark::kMillisecond);
  using Blend = ParticleLook::Blend;
  benchmark::RegisterBenchmark("build_1e5_sprites/additive", buildSprites, Blend::Additive)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("build_1e5_sprites/alpha", buildSprites, Blend::Alpha)->Unit(benchmark::kMillisecond);
  // llvmpipe draws on threads of its own: the rate is per wall-clock second, not per CPU second
  // of this thread.
  benchmark::RegisterBenchmark("render_no_sprites", renderNoSprites)->Unit(benchmark::kMillisecond)->UseRealTime();
  benchmark::RegisterBenchmark("render_1e5_sprites/additive", renderSprites, Blend::Additive)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("render_1e5_sprites/alpha", renderSprites, Blend::Alpha)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printSummary(reporter);
  benchmark::Shutdown();
  return 0;
}
