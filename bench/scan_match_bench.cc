// The pose tracker's correction step: correlative scan matching of a whole
// pirouette's hits against the hits seen before (localize::MatchScan, Olson
// 2009: a lookup field of each point's agreement, stamped once, then every
// candidate pose is a sum of lookups) against the straightforward version:
// the same search over the same candidates with the same likelihood, each
// hit's agreement from its nearest reference hit found with OpenCV's k-d
// tree (cv::flann, exact search) at the centre of the hit's cell, as the
// field has it, and none beyond the field's kernel. Both return the
// posterior's mean; the counter `agree_m` is how far apart the two answers
// are. The k-d tree is built outside the timed loop, the field inside it.
//
//   build/release/bench/pirouette_bench --benchmark_filter='scan_match/'
//
// Names follow `scan_match/<who>/<prior σ in mm>`: a 3 m × 2 m room with a
// box, the reference sampled every 5 mm, a pirouette of 360 hits out to
// 1.2 m seen from 4 cm and 1.5° away from where the robot believes it is;
// the prior's heading σ is 1.5° (the tracker's 3° is in the last case).

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <opencv2/flann.hpp>
#include <vector>

#include "pirouette/localize/scan_matcher.h"

namespace {

using pirouette::localize::HitStore;
using pirouette::localize::MatchScan;
using pirouette::localize::ScanMatchOptions;

constexpr double kDeg = std::numbers::pi / 180.0;

std::vector<Eigen::Vector2d> Room(double step) {
  std::vector<Eigen::Vector2d> p;
  const auto segment = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const double length = (b - a).norm();
    for (double s = 0.0; s <= length; s += step) p.emplace_back(a + (b - a) * (s / length));
  };
  const Eigen::Vector2d c[] = {{0, 0}, {3, 0}, {3, 2}, {0, 2}};
  const Eigen::Vector2d b[] = {{1.8, 0.6}, {2.2, 0.6}, {2.2, 1.1}, {1.8, 1.1}};
  for (int i = 0; i < 4; ++i) {
    segment(c[i], c[(i + 1) % 4]);
    segment(b[i], b[(i + 1) % 4]);
  }
  return p;
}

// The nearest wall point along each degree of bearing from `truth`, out to
// 1.2 m, as offsets in a frame turned by `heading_error`.
std::vector<Eigen::Vector2d> Pirouette(const Eigen::Vector2d& truth, double heading_error) {
  const std::vector<Eigen::Vector2d> walls = Room(0.002);
  std::vector<Eigen::Vector2d> nearest(360, Eigen::Vector2d::Zero());
  std::vector<double> range(360, std::numeric_limits<double>::infinity());
  for (const Eigen::Vector2d& p : walls) {
    const Eigen::Vector2d d = p - truth;
    const double r = d.norm();
    if (r > 1.2) continue;
    const int bin = static_cast<int>(std::floor((std::atan2(d.y(), d.x()) / kDeg) + 180.0)) % 360;
    if (r < range[bin]) {
      range[bin] = r;
      nearest[bin] = Eigen::Rotation2Dd(-heading_error) * d;
    }
  }
  std::vector<Eigen::Vector2d> out;
  for (int b = 0; b < 360; ++b) {
    if (std::isfinite(range[b])) out.push_back(nearest[b]);
  }
  return out;
}

struct Case {
  std::vector<Eigen::Vector2d> reference = Room(0.005);
  Eigen::Vector2d truth{1.0, 0.9};
  Eigen::Vector2d believed{1.03, 0.873};  // 4 cm off
  std::vector<Eigen::Vector2d> hits = Pirouette(truth, 1.5 * kDeg);
};

const Case& BenchCase() {
  static const Case c;
  return c;
}

Eigen::Matrix3d Prior(double sigma_m, double sigma_rad) {
  return Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, sigma_rad * sigma_rad).asDiagonal();
}

// The same search as MatchScan (the same candidates, likelihood and prior),
// each hit's agreement from the distance to its nearest reference hit.
Eigen::Vector3d Straightforward(cv::flann::Index& index, const Eigen::Vector2d& origin,
                                const std::vector<Eigen::Vector2d>& hits,
                                const Eigen::Matrix3d& prior, const ScanMatchOptions& o) {
  const auto window = [&](double variance) {
    return std::clamp(o.window_sigmas * std::sqrt(variance), o.min_window_m, o.max_window_m);
  };
  const int nx = static_cast<int>(std::round(window(prior(0, 0)) / o.cell_m));
  const int ny = static_cast<int>(std::round(window(prior(1, 1)) / o.cell_m));
  const int nt = static_cast<int>(std::ceil(o.window_sigmas * std::sqrt(prior(2, 2)) / o.step_rad));
  const Eigen::Matrix3d information = prior.inverse();
  const double kernel_m = std::ceil(3.0 * o.sigma_m / o.cell_m) * o.cell_m;
  cv::Mat queries(static_cast<int>(hits.size()), 2, CV_32F);
  cv::Mat indices;
  cv::Mat distances;
  std::vector<std::pair<Eigen::Vector3d, double>> scored;
  double best = -std::numeric_limits<double>::infinity();
  for (int k = -nt; k <= nt; ++k) {
    const Eigen::Rotation2Dd turn(k * o.step_rad);
    for (int iy = -ny; iy <= ny; ++iy) {
      for (int ix = -nx; ix <= nx; ++ix) {
        const Eigen::Vector3d offset(ix * o.cell_m, iy * o.cell_m, k * o.step_rad);
        for (std::size_t i = 0; i < hits.size(); ++i) {
          // The centre of the hit's cell, as MatchScan looks it up.
          const Eigen::Vector2d p =
              ((origin + turn * hits[i]) / o.cell_m).array().floor().matrix() * o.cell_m +
              offset.head<2>() + Eigen::Vector2d(0.5 * o.cell_m, 0.5 * o.cell_m);
          queries.at<float>(static_cast<int>(i), 0) = static_cast<float>(p.x());
          queries.at<float>(static_cast<int>(i), 1) = static_cast<float>(p.y());
        }
        index.knnSearch(queries, indices, distances, 1, cv::flann::SearchParams(-1));
        double sum = 0.0;
        for (int i = 0; i < distances.rows; ++i) {
          const double d2 = distances.at<float>(i, 0);  // squared L2
          // The field is stamped only within its kernel (a square; the
          // Gaussian is below 1e-4 of its peak there, so a disc is as good).
          sum += d2 <= kernel_m * kernel_m
                     ? std::log(o.floor + std::exp(-d2 / (2.0 * o.sigma_m * o.sigma_m)))
                     : std::log(o.floor);
        }
        const double lp = sum / o.correlation - 0.5 * offset.dot(information * offset);
        best = std::max(best, lp);
        scored.emplace_back(offset, lp);
      }
    }
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (const auto& [offset, lp] : scored) {
    const double w = std::exp(lp - best);
    mean += w * offset;
    total += w;
  }
  return mean / total;
}

void ScanMatchLookupField(benchmark::State& state) {
  const Case& c = BenchCase();
  HitStore store;
  for (const Eigen::Vector2d& p : c.reference) store.Add(p);
  const Eigen::Matrix3d prior = Prior(state.range(0) * 1e-3, state.range(1) * 0.1 * kDeg);
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (auto _ : state) {
    offset = MatchScan(store, c.believed, c.hits, prior).offset;
    benchmark::DoNotOptimize(offset);
  }
  state.counters["error_m"] = (c.believed + offset.head<2>() - c.truth).norm();
  state.counters["hits"] = static_cast<double>(c.hits.size());
}

void ScanMatchKdTree(benchmark::State& state) {
  const Case& c = BenchCase();
  HitStore store;
  for (const Eigen::Vector2d& p : c.reference) store.Add(p);
  // The same reference points (HitStore's cell centres).
  const std::vector<Eigen::Vector2d> cells =
      store.Within(Eigen::Vector2d(-1e9, -1e9), Eigen::Vector2d(1e9, 1e9));
  cv::Mat points(static_cast<int>(cells.size()), 2, CV_32F);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    points.at<float>(static_cast<int>(i), 0) = static_cast<float>(cells[i].x());
    points.at<float>(static_cast<int>(i), 1) = static_cast<float>(cells[i].y());
  }
  cv::flann::Index index(points, cv::flann::KDTreeIndexParams(1));
  const Eigen::Matrix3d prior = Prior(state.range(0) * 1e-3, state.range(1) * 0.1 * kDeg);
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (auto _ : state) {
    offset = Straightforward(index, c.believed, c.hits, prior, ScanMatchOptions{});
    benchmark::DoNotOptimize(offset);
  }
  state.counters["error_m"] = (c.believed + offset.head<2>() - c.truth).norm();
  const Eigen::Vector3d field = MatchScan(store, c.believed, c.hits, prior).offset;
  state.counters["agree_m"] = (field.head<2>() - offset.head<2>()).norm();
}

// {prior σ in mm, heading σ in tenths of a degree}
BENCHMARK(ScanMatchLookupField)
    ->Name("scan_match/lookup-field")
    ->Args({20, 15})
    ->Args({40, 15})
    ->Args({40, 30})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(ScanMatchKdTree)
    ->Name("scan_match/opencv-kdtree")
    ->Args({20, 15})
    ->Args({40, 15})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace
