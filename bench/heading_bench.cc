// The stop tracker's heading match of a new frame against the frames taken
// before it at the same stop (localize::MatchToViews: every reading compared
// with the views along the same bearing, over a window of ±3σ in steps of
// 0.05°) against the straightforward version: the same search, with each
// view's columns scanned for the pair either side of the bearing, as the
// matcher did before 2026-12-05, where pirouette bisects them. The counter
// `agree_deg` is how far apart the two answers are.
//
//   build/release/bench/pirouette_bench --benchmark_filter='heading/'
//
// Names follow `heading/<who>/<columns>`: a 1.2 m × 1 m room seen from
// 0.14 m off its centre, a 60° camera of that many columns reading out to
// 0.874 m (the apartment robot's), two views at 0° and 30°, and a frame at
// 60° predicted 1° off, σ 1.5° (5% rotation noise on a 30° turn).

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/localize/heading_matcher.h"

namespace {

using pirouette::core::ObstacleProfile;
using pirouette::core::RangeReading;
using pirouette::core::ReadingKind;
using pirouette::localize::HeadedView;
using pirouette::localize::HeadingMatcherOptions;

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMaxRangeM = 0.874;

// The distance along `bearing` (world) from `from` to the walls of the room
// [-0.6, 0.6] × [-0.5, 0.5].
double ToWall(const Eigen::Vector2d& from, double bearing) {
  const Eigen::Vector2d d(std::cos(bearing), std::sin(bearing));
  double t = std::numeric_limits<double>::infinity();
  if (d.x() > 0) t = std::min(t, (0.6 - from.x()) / d.x());
  if (d.x() < 0) t = std::min(t, (-0.6 - from.x()) / d.x());
  if (d.y() > 0) t = std::min(t, (0.5 - from.y()) / d.y());
  if (d.y() < 0) t = std::min(t, (-0.5 - from.y()) / d.y());
  return t;
}

ObstacleProfile View(double heading, int columns) {
  const Eigen::Vector2d at(0.1, -0.1);
  ObstacleProfile p;
  p.max_range_m = kMaxRangeM;
  for (int i = 0; i < columns; ++i) {
    const double bearing = 30.0 * kDeg - 60.0 * kDeg * i / (columns - 1);
    const double r = ToWall(at, heading + bearing);
    p.readings.push_back(r < kMaxRangeM ? RangeReading{bearing, r, ReadingKind::kHit}
                                        : RangeReading{bearing, kMaxRangeM, ReadingKind::kClear});
  }
  return p;
}

// The straightforward version of MatchToViews: the same search and
// agreement, each view's columns scanned for the bracket.
double AgreesWith(const RangeReading& reading, ReadingKind other_kind, double other_range_m,
                  const HeadingMatcherOptions& o) {
  const bool hit = reading.kind == ReadingKind::kHit;
  const bool other_hit = other_kind != ReadingKind::kClear;
  if (hit && other_hit) {
    const double s = std::max(o.view_sigma_floor_m, o.view_sigma_fraction * reading.range_m);
    const double d = reading.range_m - other_range_m;
    return std::exp(-d * d / (2.0 * s * s));
  }
  return !hit && !other_hit ? 1.0 : 0.0;
}

std::optional<double> ScannedAgreementAt(const RangeReading& reading, const ObstacleProfile& view,
                                         double bearing, const HeadingMatcherOptions& o) {
  const std::vector<RangeReading>& r = view.readings;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    const double hi = r[i].bearing_rad;
    const double lo = r[i + 1].bearing_rad;
    if (bearing > hi || bearing < lo) continue;
    if ((r[i].kind != ReadingKind::kClear) != (r[i + 1].kind != ReadingKind::kClear) ||
        hi - lo <= 0.0) {
      return std::max(AgreesWith(reading, r[i].kind, r[i].range_m, o),
                      AgreesWith(reading, r[i + 1].kind, r[i + 1].range_m, o));
    }
    const double t = (hi - bearing) / (hi - lo);
    return AgreesWith(reading, r[i].kind, (1.0 - t) * r[i].range_m + t * r[i + 1].range_m, o);
  }
  return std::nullopt;
}

bool InView(const ObstacleProfile& p, double bearing) {
  return bearing <= p.readings.front().bearing_rad && bearing >= p.readings.back().bearing_rad;
}

double ScannedMatch(const std::vector<HeadedView>& views, const ObstacleProfile& profile,
                    double predicted, double sigma, const HeadingMatcherOptions& o) {
  using pirouette::core::NormalizeAngle;
  const int n = static_cast<int>(std::ceil(3.0 * sigma / o.step_rad));
  std::vector<std::pair<const RangeReading*, const HeadedView*>> kept;
  for (const RangeReading& reading : profile.readings) {
    for (const HeadedView& view : views) {
      const double base = predicted + reading.bearing_rad - view.heading_rad;
      if (InView(*view.profile, NormalizeAngle(base - 3.0 * sigma)) &&
          InView(*view.profile, NormalizeAngle(base + 3.0 * sigma))) {
        kept.emplace_back(&reading, &view);
        break;
      }
    }
  }
  double best = -std::numeric_limits<double>::infinity();
  double answer = 0.0;
  for (int k = -n; k <= n; ++k) {
    const double offset = k * o.step_rad;
    double sum = 0.0;
    for (const auto& [reading, view] : kept) {
      const std::optional<double> a = ScannedAgreementAt(
          *reading, *view->profile,
          NormalizeAngle(predicted + offset + reading->bearing_rad - view->heading_rad), o);
      if (a) sum += *a;
    }
    const double objective = sum - o.prior_weight * 0.5 * (offset / sigma) * (offset / sigma);
    if (objective > best) {
      best = objective;
      answer = offset;
    }
  }
  return answer;
}

struct Scene {
  explicit Scene(int columns)
      : first(View(0.0, columns)),
        second(View(30.0 * kDeg, columns)),
        frame(View(60.0 * kDeg, columns)) {}
  ObstacleProfile first;
  ObstacleProfile second;
  ObstacleProfile frame;
  std::vector<HeadedView> Views() const { return {{&first, 0.0}, {&second, 30.0 * kDeg}}; }
  static constexpr double kPredicted = 59.0 * kDeg;
  static constexpr double kSigma = 1.5 * kDeg;
};

void HeadingPirouette(benchmark::State& state) {
  const Scene scene(static_cast<int>(state.range(0)));
  const std::vector<HeadedView> views = scene.Views();
  const HeadingMatcherOptions options;
  double offset = 0.0;
  for (auto _ : state) {
    // DoNotOptimize of a const value: GCC 12 garbles a double passed as the
    // read-write operand.
    const double found = pirouette::localize::MatchToViews(views, scene.frame, Scene::kPredicted,
                                                           Scene::kSigma, options)
                             .offset_rad;
    benchmark::DoNotOptimize(found);
    offset = found;
  }
  const double other = ScannedMatch(views, scene.frame, Scene::kPredicted, Scene::kSigma, options);
  state.counters["agree_deg"] = std::abs(offset - other) / kDeg;
  state.counters["offset_deg"] = offset / kDeg;
}

void HeadingScanned(benchmark::State& state) {
  const Scene scene(static_cast<int>(state.range(0)));
  const std::vector<HeadedView> views = scene.Views();
  const HeadingMatcherOptions options;
  double offset = 0.0;
  for (auto _ : state) {
    const double found =
        ScannedMatch(views, scene.frame, Scene::kPredicted, Scene::kSigma, options);
    benchmark::DoNotOptimize(found);
    offset = found;
  }
  state.counters["offset_deg"] = offset / kDeg;
}

}  // namespace

BENCHMARK(HeadingPirouette)
    ->Name("heading/pirouette")
    ->Arg(320)
    ->Arg(640)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(HeadingScanned)
    ->Name("heading/straightforward")
    ->Arg(320)
    ->Arg(640)
    ->Unit(benchmark::kMillisecond);
