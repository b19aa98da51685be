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
#include <filesystem>
#include <memory>
#include <string>

#include "bench_worlds.h"
#include "pirouette/core/angle.h"
#include "pirouette/sim/block_grid.h"
#include "pirouette/sim/ray_caster.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/world_spec.h"
#include "pirouette/tools/world_from_map.h"
#include "pirouette/tools/world_generate.h"

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

// A digital twin's scale (issue 20): a 20 x 20 m apartment (generated, seed
// 1) rasterised at 5 cm, each occupied cell a block, merged into boxes as
// `world from-map` does (sim::BlockGridSolids) -- against the shipped
// apartment (8 x 6 m, 30 prisms) at the apartment robot's 640 x 480.
const World& GridWorld20m() {
  static const World world = [] {
    const World drawn = pirouette::sim::BuildWorld(
        pirouette::tools::GenerateValidWorld(pirouette::sim::WorldKind::kApartment, 1,
                                             Eigen::Vector2d(20.0, 20.0))
            .spec);
    pirouette::sim::BlockGrid grid{pirouette::core::GridGeometry(0.05, {0.0, 0.0}, 400, 400), {}};
    for (std::size_t i = 0; i < grid.geometry.CellCount(); ++i) {
      const Eigen::Vector2d c = grid.geometry.CellCentre(grid.geometry.Unflat(i));
      grid.solid.push_back(drawn.IsOccupied(c) ? 1 : 0);
    }
    return World("grid-20m", drawn.floor(), std::nullopt,
                 pirouette::sim::BlockGridSolids(grid, 0.9, {235, 230, 220}), drawn.light(),
                 drawn.robot());
  }();
  return world;
}

const World& Apartment() {
  static const World world =
      pirouette::io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/apartment.yaml");
  return world;
}

// The real office's twin (../shared/realdata/maps/tb3_office, made as
// `world from-map` makes it), where the data are present.
const World* OfficeTwin() {
  static const std::unique_ptr<World> world = []() -> std::unique_ptr<World> {
    pirouette::tools::WorldFromMapRequest request;
    request.map_path =
        std::string(PIROUETTE_SHARED_DIR) + "/realdata/maps/tb3_office/map_office_raw.yaml";
    if (!std::filesystem::exists(request.map_path)) return nullptr;
    request.out_path =
        (std::filesystem::temp_directory_path() / "pirouette_bench_office.yaml").string();
    pirouette::tools::RunWorldFromMap(request);
    auto loaded = std::make_unique<World>(pirouette::io::LoadWorldFile(request.out_path));
    std::filesystem::remove(request.out_path);
    return loaded;
  }();
  return world.get();
}

// A pirouette at the world's start, 30 degrees a frame.
void RenderWorld(benchmark::State& state, const World& world) {
  pirouette::sim::Renderer renderer(world, world.robot().camera, {});
  state.SetLabel(std::to_string(world.solids().size()) + " solids");
  const Pose2 start = world.robot().start;
  double heading = start.heading();
  const auto begin = std::chrono::steady_clock::now();
  for (auto _ : state) {
    heading += pirouette::core::DegToRad(30.0);
    benchmark::DoNotOptimize(renderer.Render(Pose2(start.x(), start.y(), heading)));
  }
  SetFramesPerSecond(state, begin);
}

BENCHMARK_CAPTURE(RenderWorld, grid, GridWorld20m())
    ->Name("render/grid-20m-5cm/640x480")
    ->Unit(benchmark::kMillisecond);
void RenderOfficeTwin(benchmark::State& state) {
  const World* world = OfficeTwin();
  if (world == nullptr) {
    state.SkipWithError("no ../shared/realdata/maps/tb3_office");
    return;
  }
  RenderWorld(state, *world);
}

BENCHMARK(RenderOfficeTwin)->Name("render/twin-tb3-office/640x480")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderWorld, apartment, Apartment())
    ->Name("render/apartment/640x480")
    ->Unit(benchmark::kMillisecond);

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
