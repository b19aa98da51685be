// The renderer's frames per second on the CPU path (Mesa's llvmpipe through
// EGL where there is no GPU), against the straightforward version: a plain
// CPU ray caster of the same scene (sim::RayCaster, the simulator's ground
// truth: floor and vertical prisms, the same shading, the same lens and
// vignetting, one ray a pixel, no anti-aliasing).
//
//   build/release/bench/pirouette_bench --benchmark_filter='render/'
//
// Names follow `<stage>/<who>/<size>`. Read the Time column (wall clock)
// and the fps counter (frames per wall-clock second): llvmpipe renders on
// its own threads, which the CPU column (the calling thread's) misses.
// LP_NUM_THREADS=1 in the environment keeps llvmpipe to one core.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "bench_worlds.h"
#include "pirouette/core/angle.h"
#include "pirouette/sim/ray_caster.h"
#include "pirouette/sim/renderer.h"

namespace {

using pirouette::camera::CameraModel;
using pirouette::core::Pose2;
using pirouette::sim::World;

using pirouette::bench::Scaled;
using pirouette::bench::SoccerField;

// Frames per wall-clock second since `start`.
void SetFramesPerSecond(benchmark::State& state, std::chrono::steady_clock::time_point start) {
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  state.counters["fps"] = static_cast<double>(state.iterations()) / elapsed.count();
}

void RenderPirouette(benchmark::State& state, int width, int height) {
  const World& world = SoccerField();
  const CameraModel camera = Scaled(world.robot().camera, width, height);
  pirouette::sim::Renderer renderer(world, camera, {});
  state.SetLabel(renderer.gl_renderer());
  double heading = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    heading += pirouette::core::DegToRad(30.0);
    benchmark::DoNotOptimize(renderer.Render(Pose2(0.75, 0.65, heading)));
  }
  SetFramesPerSecond(state, start);
}

void RenderRayCaster(benchmark::State& state, int width, int height) {
  const World& world = SoccerField();
  const pirouette::sim::RayCaster caster(world, Scaled(world.robot().camera, width, height));
  double heading = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    heading += pirouette::core::DegToRad(30.0);
    benchmark::DoNotOptimize(caster.Render(Pose2(0.75, 0.65, heading)));
  }
  SetFramesPerSecond(state, start);
}

BENCHMARK_CAPTURE(RenderPirouette, 320x240, 320, 240)
    ->Name("render/pirouette/320x240")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderRayCaster, 320x240, 320, 240)
    ->Name("render/straightforward/320x240")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderPirouette, 640x480, 640, 480)
    ->Name("render/pirouette/640x480")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderRayCaster, 640x480, 640, 480)
    ->Name("render/straightforward/640x480")
    ->Unit(benchmark::kMillisecond);

}  // namespace
