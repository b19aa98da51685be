// The converged chamfer distance transform that respects obstacles
// (explore::ChamferDistanceTransform, Taylor, Geva & Boles 2005, §4) against
// OpenCV's cv::distanceTransform (DIST_L2, 3 × 3 mask), which runs its two
// raster passes once and ignores obstacles: it does less.
//
//   build/release/bench/pirouette_bench --benchmark_filter='dt/'
//
// Names follow `<stage>/<who>/<size>`: N × N grids of random rectangles
// covering about 20% of the cells and 64 goal cells, the same for both.
// dt/bucket-queue/N is pirouette's other exact algorithm (Dial's), for
// reference.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "pirouette/explore/coarse_grid.h"
#include "pirouette/explore/distance_transform.h"

namespace {

using pirouette::explore::CoarseCell;
using pirouette::explore::CoarseGrid;

// An N × N grid: random rectangles (sides 1 to N/16 cells) until 20% of the
// cells are blocked, then 64 goals on free cells. Deterministic.
const CoarseGrid& BenchGrid(int n) {
  static std::vector<std::pair<int, CoarseGrid>> grids;
  for (const auto& [size, grid] : grids) {
    if (size == n) return grid;
  }
  std::mt19937 rng(2005);
  const auto uniform = [&](int m) { return static_cast<int>(rng() % static_cast<unsigned>(m)); };
  std::vector<CoarseCell> cells(static_cast<std::size_t>(n) * n, CoarseCell::kFree);
  std::size_t blocked = 0;
  const int max_side = std::max(1, n / 16);
  while (blocked < cells.size() / 5) {
    const int w = 1 + uniform(max_side);
    const int h = 1 + uniform(max_side);
    const int x0 = uniform(n - w + 1);
    const int y0 = uniform(n - h + 1);
    for (int y = y0; y < y0 + h; ++y) {
      for (int x = x0; x < x0 + w; ++x) {
        CoarseCell& c = cells[static_cast<std::size_t>(y) * n + x];
        if (c != CoarseCell::kBlocked) ++blocked;
        c = CoarseCell::kBlocked;
      }
    }
  }
  for (int goals = 0; goals < 64;) {
    CoarseCell& c = cells[static_cast<std::size_t>(uniform(n * n))];
    if (c == CoarseCell::kFree) {
      c = CoarseCell::kGoal;
      ++goals;
    }
  }
  grids.emplace_back(
      n, CoarseGrid(pirouette::core::GridGeometry(1.0, {0.0, 0.0}, n, n), std::move(cells)));
  return grids.back().second;
}

void DtPirouette(benchmark::State& state, pirouette::explore::DistanceAlgorithm algorithm) {
  const CoarseGrid& grid = BenchGrid(static_cast<int>(state.range(0)));
  int sweeps = 0;
  for (auto _ : state) {
    const auto field = pirouette::explore::ChamferDistanceTransform(grid, {algorithm});
    sweeps = field.sweeps();
    benchmark::DoNotOptimize(field);
  }
  if (sweeps > 0) state.counters["sweeps"] = sweeps;
}

void DtOpenCv(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const CoarseGrid& grid = BenchGrid(n);
  cv::Mat src(n, n, CV_8UC1);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      src.at<std::uint8_t>(y, x) =
          grid.cells()[static_cast<std::size_t>(y) * n + x] == CoarseCell::kGoal ? 0 : 255;
    }
  }
  cv::Mat dst;
  for (auto _ : state) {
    cv::distanceTransform(src, dst, cv::DIST_L2, 3);
    benchmark::DoNotOptimize(dst.data);
  }
}

BENCHMARK_CAPTURE(DtPirouette, sweeps, pirouette::explore::DistanceAlgorithm::kRasterSweeps)
    ->Name("dt/pirouette")
    ->Arg(512)
    ->Arg(2048)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(DtOpenCv)->Name("dt/opencv")->Arg(512)->Arg(2048)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(DtPirouette, buckets, pirouette::explore::DistanceAlgorithm::kBucketQueue)
    ->Name("dt/bucket-queue")
    ->Arg(512)
    ->Arg(2048)
    ->Unit(benchmark::kMillisecond);

}  // namespace
