// The pose graph's optimisation after a stop (localize::PoseGraph::Optimise,
// Ceres, sparse Cholesky) as GraphTracker runs it, against the
// straightforward version the issue names: re-solving the whole graph from
// scratch each stop, from the odometry's dead reckoning.
//
//   build/release/bench/pirouette_bench --benchmark_filter='graph/'
//
// Names follow `graph/<who>/<stops>`: stops every 0.3 m along a lawnmower
// path through a 6 m × 6 m floor (rows 0.6 m apart, as an exploration
// sweeps a large room), odometry edges with 5% noise (seeded), a scan-match
// edge to the stop before (1 cm, 0.5°) and a loop closure to the nearest
// stop more than 2 m back along the path within 0.6 m (the row before).
// `pirouette`: the graph of stops-1 stops already optimised, one stop and its
// edges added, optimised from there (the estimates of the stops before are
// the last solution's, the new one from its odometry edge). `scratch`: the
// same graph solved from dead reckoning. The graph is copied outside the
// timed region. The counter `error_rms_m` is the solution's stops against
// the truth.

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pirouette/localize/pose_graph.h"

namespace {

using pirouette::core::Pose2;
using pirouette::localize::EdgeKind;
using pirouette::localize::PoseGraph;
using pirouette::localize::PoseGraphEdge;

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Matrix3d Information(double sigma_m, double sigma_rad) {
  return Eigen::Vector3d(1.0 / (sigma_m * sigma_m), 1.0 / (sigma_m * sigma_m),
                         1.0 / (sigma_rad * sigma_rad))
      .asDiagonal();
}

// The true stops along the lawnmower path.
std::vector<Pose2> Path(int stops) {
  std::vector<Pose2> path;
  constexpr double kStep = 0.3;
  constexpr double kRow = 0.6;
  constexpr int kPerRow = 20;  // 6 m
  for (int i = 0; i < stops; ++i) {
    const int row = i / kPerRow;
    const int k = i % kPerRow;
    const bool back = row % 2 == 1;
    const double x = back ? (kPerRow - 1 - k) * kStep : k * kStep;
    path.emplace_back(x, row * kRow, back ? std::numbers::pi : 0.0);
  }
  return path;
}

// The edges of stop i (into it), from the truth with seeded noise.
std::vector<PoseGraphEdge> EdgesInto(int i, const std::vector<Pose2>& truth, std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<PoseGraphEdge> edges;
  if (i == 0) return edges;
  const Pose2 step = truth[i - 1].Inverse() * truth[i];
  const double d = step.translation().norm();
  const double turn = std::abs(step.heading()) + 2.0 * std::numbers::pi;  // a pirouette between
  const Pose2 noisy(step.x() * (1.0 + 0.05 * n(rng)), step.y() + 0.05 * d * n(rng),
                    step.heading() + 0.05 * turn * n(rng));
  edges.push_back(
      {i - 1, i, noisy, Information(0.05 * d + 0.002, 0.05 * turn), EdgeKind::kOdometry});
  edges.push_back({i - 1, i,
                   Pose2(step.x() + 0.01 * n(rng), step.y() + 0.01 * n(rng),
                         step.heading() + 0.5 * kDeg * n(rng)),
                   Information(0.01, 0.5 * kDeg), EdgeKind::kScanMatch});
  // The nearest stop in the row before.
  int best = -1;
  double best_m = 0.6;
  for (int j = 0; j + 7 < i; ++j) {
    const double m = (truth[j].translation() - truth[i].translation()).norm();
    if (m <= best_m) {
      best_m = m;
      best = j;
    }
  }
  if (best >= 0) {
    const Pose2 rel = truth[best].Inverse() * truth[i];
    edges.push_back({best, i,
                     Pose2(rel.x() + 0.01 * n(rng), rel.y() + 0.01 * n(rng),
                           rel.heading() + 0.5 * kDeg * n(rng)),
                     Information(0.01, 0.5 * kDeg), EdgeKind::kLoopClosure});
  }
  return edges;
}

// The graph of `stops` stops, each optimised as it came (GraphTracker's way)
// but the last, which is added and left at its odometry estimate; and
// `scratch`: the same edges with every node at its dead reckoning.
void MakeGraphs(int stops, PoseGraph& incremental, PoseGraph& scratch) {
  const std::vector<Pose2> truth = Path(stops);
  std::mt19937 rng(7);
  std::vector<std::vector<PoseGraphEdge>> edges;
  for (int i = 0; i < stops; ++i) edges.push_back(EdgesInto(i, truth, rng));
  Pose2 reckoned = truth[0];
  for (int i = 0; i < stops; ++i) {
    if (i > 0) reckoned = reckoned * edges[i][0].from_T_to;
    scratch.AddNode(reckoned);
    const Pose2 guess = i == 0 ? truth[0] : incremental.pose(i - 1) * edges[i][0].from_T_to;
    incremental.AddNode(guess);
    for (const PoseGraphEdge& e : edges[i]) {
      scratch.AddEdge(e);
      incremental.AddEdge(e);
    }
    if (i + 1 < stops) incremental.Optimise();
  }
}

void Run(benchmark::State& state, bool from_scratch) {
  const int stops = static_cast<int>(state.range(0));
  PoseGraph incremental;
  PoseGraph scratch;
  MakeGraphs(stops, incremental, scratch);
  const PoseGraph& start = from_scratch ? scratch : incremental;
  PoseGraph solved;
  for (auto _ : state) {
    state.PauseTiming();
    PoseGraph graph = start;
    state.ResumeTiming();
    graph.Optimise();
    benchmark::DoNotOptimize(graph.poses().data());
    state.PauseTiming();
    solved = std::move(graph);
    state.ResumeTiming();
  }
  // How far the solution's stops are from the truth (RMS): a solve from
  // dead reckoning after long drift may end in another minimum.
  const std::vector<Pose2> truth = Path(stops);
  double sum = 0.0;
  for (int i = 0; i < stops; ++i) {
    sum += (solved.pose(i).translation() - truth[static_cast<std::size_t>(i)].translation())
               .squaredNorm();
  }
  state.counters["error_rms_m"] = std::sqrt(sum / stops);
  state.counters["edges"] = static_cast<double>(solved.edges().size());
}

void BM_GraphPirouette(benchmark::State& state) { Run(state, false); }
void BM_GraphScratch(benchmark::State& state) { Run(state, true); }

BENCHMARK(BM_GraphPirouette)
    ->Name("graph/pirouette")
    ->Arg(50)
    ->Arg(200)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GraphScratch)
    ->Name("graph/scratch")
    ->Arg(50)
    ->Arg(200)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);

}  // namespace
