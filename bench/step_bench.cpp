// Cost of one World::step per integrator, for a box and for a body whose world vertices are
// many (the p' = R p + x update of seed 004 dominates there), and of exact mass properties.
// Run: build/bench/step_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "rbsim/mass/mass_model.h"
#include "rbsim/world/world.h"

namespace {

using namespace rbsim;

// A closed, outward-wound UV sphere of `rings` x `segments` quads: a mesh with many vertices.
Mesh makeSphere(int rings, int segments, double radius) {
  Mesh mesh;
  mesh.name = "sphere";
  mesh.vertices.push_back({0, radius, 0});
  for (int r = 1; r < rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2 * M_PI * s / segments;
      mesh.vertices.push_back(radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
    }
  }
  mesh.vertices.push_back({0, -radius, 0});
  const auto ring = [&](int r, int s) { return static_cast<std::uint32_t>(1 + (r - 1) * segments + (s % segments)); };
  const std::uint32_t south = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
  for (int s = 0; s < segments; ++s) {
    mesh.triangles.push_back({0, ring(1, s + 1), ring(1, s)});
    mesh.triangles.push_back({south, ring(rings - 1, s), ring(rings - 1, s + 1)});
    for (int r = 1; r < rings - 1; ++r) {
      mesh.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s + 1)});
      mesh.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r + 1, s)});
    }
  }
  return mesh;
}

World makeWorld(Integrator integrator, Mesh mesh) {
  Settings settings;
  settings.integrator = integrator;
  World world(settings);
  const MassModel model = buildMassModel(std::move(mesh), 1.0, std::nullopt, InertiaMethod::Exact);
  BodyDef def;
  def.mesh = model.mesh;
  def.mass = model.mass;
  def.inertiaBody = model.inertiaBody;
  def.angularVelocity = Vec3(0.3, 2.0, 0.1);
  world.addBody(def);
  return world;
}

void stepBox(benchmark::State& state, Integrator integrator) {
  World world = makeWorld(integrator, makeBox(Vec3(1.0, 0.3, 0.1)));
  for (auto _ : state) {
    world.step();
    benchmark::DoNotOptimize(world.bodies().front().state());
  }
}

void stepSphere(benchmark::State& state) {
  const int rings = static_cast<int>(state.range(0));
  World world = makeWorld(Integrator::ExpMap, makeSphere(rings, 2 * rings, 0.5));
  for (auto _ : state) {
    world.step();
    benchmark::DoNotOptimize(world.bodies().front().worldVertex(0));
  }
  state.counters["vertices"] = static_cast<double>(world.bodies().front().vertexCount());
}

void massProperties(benchmark::State& state) {
  const int rings = static_cast<int>(state.range(0));
  const Mesh sphere = makeSphere(rings, 2 * rings, 0.5);
  for (auto _ : state) benchmark::DoNotOptimize(polyhedralMassProperties(sphere, 1000.0));
  state.counters["triangles"] = static_cast<double>(sphere.triangles.size());
}

BENCHMARK_CAPTURE(stepBox, euler_matrix, Integrator::EulerMatrix);
BENCHMARK_CAPTURE(stepBox, euler_quat, Integrator::EulerQuat);
BENCHMARK_CAPTURE(stepBox, expmap, Integrator::ExpMap);
BENCHMARK(stepSphere)->Arg(16)->Arg(64)->Arg(256);
BENCHMARK(massProperties)->Arg(16)->Arg(64)->Arg(256);

}  // namespace
