#include "pirouette/localize/heading_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "pirouette/core/angle.h"

namespace pirouette::localize {

namespace {

// The ray from `origin` along `bearing` through `grid` (see MapProfile).
MapRay CastRay(const mapping::OccupancyGrid& grid, const Eigen::Vector2d& origin, double bearing,
               double max_range_m) {
  const double step = 0.5 * grid.geometry().resolution();
  const Eigen::Vector2d d(std::cos(bearing), std::sin(bearing));
  for (double r = 0.0; r <= max_range_m; r += step) {
    const core::CellIndex c = grid.geometry().CellOf(origin + r * d);
    const mapping::CellState state = grid.State(c);
    if (state == mapping::CellState::kOccupied) {
      return {MapRay::Kind::kHit, (grid.geometry().CellCentre(c) - origin).dot(d)};
    }
    if (state != mapping::CellState::kFree) return {MapRay::Kind::kUnknown, r};
  }
  return {MapRay::Kind::kClear, max_range_m};
}

}  // namespace

void HeadingMatcherOptions::Check() const {
  if (!(step_rad > 0.0) || !(step_rad < 1.0) || !(sigma_floor_m > 0.0) ||
      !(sigma_fraction >= 0.0) || !(view_sigma_floor_m > 0.0) || !(view_sigma_fraction >= 0.0) ||
      !(prior_weight >= 0.0) || min_compared < 1) {
    throw std::invalid_argument(
        "HeadingMatcherOptions: the step must be in (0, 1) rad, the sigmas' floors > 0, the "
        "fractions and the prior's weight >= 0 and min_compared >= 1");
  }
}

MapProfile::MapProfile(const mapping::OccupancyGrid& grid, const Eigen::Vector2d& origin,
                       double max_range_m, int bins)
    : rays_(static_cast<std::size_t>(std::max(bins, 0))) {
  if (bins < 1 || !(max_range_m >= 0.0) || !std::isfinite(max_range_m)) {
    throw std::invalid_argument("MapProfile: bins must be >= 1 and the max range finite, >= 0");
  }
  for (int b = 0; b < bins; ++b) {
    rays_[static_cast<std::size_t>(b)] =
        CastRay(grid, origin, 2.0 * std::numbers::pi * (b + 0.5) / bins, max_range_m);
  }
}

const MapRay& MapProfile::At(double bearing_rad) const {
  const double turns = bearing_rad / (2.0 * std::numbers::pi);
  const double frac = turns - std::floor(turns);
  const int n = bins();
  const int b = std::min(n - 1, static_cast<int>(frac * n));
  return rays_[static_cast<std::size_t>(b)];
}

namespace {

// How well one (not blind) reading agrees with the map's (known) ray.
double Agrees(const core::RangeReading& reading, const MapRay& ray,
              const HeadingMatcherOptions& options) {
  const bool hit = reading.kind == core::ReadingKind::kHit;
  if (hit && ray.kind == MapRay::Kind::kHit) {
    const double sigma = std::max(options.sigma_floor_m, options.sigma_fraction * reading.range_m);
    const double d = reading.range_m - ray.range_m;
    return std::exp(-d * d / (2.0 * sigma * sigma));
  }
  return !hit && ray.kind == MapRay::Kind::kClear ? 1.0 : 0.0;
}

}  // namespace

HeadingMatch MatchHeading(const MapProfile& map, const core::ObstacleProfile& profile,
                          double predicted_heading, double sigma_rad,
                          const HeadingMatcherOptions& options) {
  options.Check();
  HeadingMatch match;
  const double sigma = std::max(sigma_rad, options.step_rad);
  const int n = static_cast<int>(std::ceil(3.0 * sigma / options.step_rad));
  // The readings whose rays the map knows all over the window.
  std::vector<const core::RangeReading*> kept;
  constexpr int kChecks = 8;
  for (const core::RangeReading& reading : profile.readings) {
    if (reading.kind == core::ReadingKind::kBlind) continue;
    bool known = true;
    for (int k = -kChecks; k <= kChecks && known; ++k) {
      const double offset = 3.0 * sigma * k / kChecks;
      known =
          map.At(predicted_heading + offset + reading.bearing_rad).kind != MapRay::Kind::kUnknown;
    }
    if (known) kept.push_back(&reading);
  }
  match.compared = static_cast<int>(kept.size());
  if (match.compared < options.min_compared) return match;
  const auto sum_at = [&](double offset) {
    double sum = 0.0;
    for (const core::RangeReading* r : kept) {
      sum += Agrees(*r, map.At(predicted_heading + offset + r->bearing_rad), options);
    }
    return sum;
  };
  double best = -std::numeric_limits<double>::infinity();
  for (int k = -n; k <= n; ++k) {
    const double offset = k * options.step_rad;
    const double objective =
        sum_at(offset) - options.prior_weight * 0.5 * (offset / sigma) * (offset / sigma);
    if (objective > best) {
      best = objective;
      match.offset_rad = offset;
    }
  }
  match.score = sum_at(match.offset_rad) / match.compared;
  match.accepted = true;
  return match;
}

namespace {

// How well `reading` agrees with two readings of one kind.
double AgreesWith(const core::RangeReading& reading, core::ReadingKind other_kind,
                  double other_range_m, const HeadingMatcherOptions& options) {
  const bool hit = reading.kind == core::ReadingKind::kHit;
  const bool other_hit = other_kind != core::ReadingKind::kClear;  // blind: nearer than seen
  if (hit && other_hit) {
    const double s =
        std::max(options.view_sigma_floor_m, options.view_sigma_fraction * reading.range_m);
    const double d = reading.range_m - other_range_m;
    return std::exp(-d * d / (2.0 * s * s));
  }
  return !hit && !other_hit ? 1.0 : 0.0;
}

// How well `reading` agrees with a view at `bearing` (the view's robot
// frame): against the view's readings interpolated between the two columns
// either side when they are of one kind; at an edge (the columns differ in
// kind) the better of the two, since the edge could lie anywhere between
// them. A blind column counts as a hit at its range (something nearer than
// the camera sees). None outside the view.
std::optional<double> AgreementAt(const core::RangeReading& reading,
                                  const core::ObstacleProfile& view, double bearing,
                                  const HeadingMatcherOptions& options) {
  const std::vector<core::RangeReading>& r = view.readings;
  // Columns run left to right: bearings decrease, nearly: a reading's
  // bearing is its floor point's, which under lens distortion moves with its
  // row, so neighbouring columns may cross by a hundredth of a degree. The
  // pair either side, i and i + 1 with r[i] >= bearing > r[i + 1] (or the
  // last pair), by bisection, which keeps that bracket whatever the order (a
  // scan of the columns for the first such pair was most of a noisy run's
  // tracking: bench/heading_bench.cc; where columns cross, the two may take
  // different brackets, both around the bearing).
  if (r.size() < 2 || !(bearing <= r.front().bearing_rad) || !(bearing >= r.back().bearing_rad)) {
    return std::nullopt;
  }
  std::size_t i = 0;
  std::size_t below = r.size() - 1;
  while (below - i > 1) {
    const std::size_t mid = i + (below - i) / 2;
    (r[mid].bearing_rad >= bearing ? i : below) = mid;
  }
  const double hi = r[i].bearing_rad;
  const double lo = r[i + 1].bearing_rad;
  const bool hit_i = r[i].kind != core::ReadingKind::kClear;
  const bool hit_j = r[i + 1].kind != core::ReadingKind::kClear;
  if (hit_i != hit_j || hi - lo <= 0.0) {
    return std::max(AgreesWith(reading, r[i].kind, r[i].range_m, options),
                    AgreesWith(reading, r[i + 1].kind, r[i + 1].range_m, options));
  }
  const double t = (hi - bearing) / (hi - lo);
  return AgreesWith(reading, r[i].kind, (1.0 - t) * r[i].range_m + t * r[i + 1].range_m, options);
}

// Whether `bearing` (robot frame) lies within the view's columns.
bool InView(const core::ObstacleProfile& profile, double bearing) {
  return !profile.readings.empty() && bearing <= profile.readings.front().bearing_rad &&
         bearing >= profile.readings.back().bearing_rad;
}

}  // namespace

HeadingMatch MatchToViews(const std::vector<HeadedView>& views,
                          const core::ObstacleProfile& profile, double predicted_heading,
                          double sigma_rad, const HeadingMatcherOptions& options) {
  options.Check();
  HeadingMatch match;
  const double sigma = std::max(sigma_rad, options.step_rad);
  const int n = static_cast<int>(std::ceil(3.0 * sigma / options.step_rad));
  // Each kept reading with the view it is compared with: the first view it
  // falls in at every offset of the window.
  std::vector<std::pair<const core::RangeReading*, const HeadedView*>> kept;
  for (const core::RangeReading& reading : profile.readings) {
    if (reading.kind == core::ReadingKind::kBlind) continue;
    for (const HeadedView& view : views) {
      const double base = predicted_heading + reading.bearing_rad - view.heading_rad;
      if (InView(*view.profile, core::NormalizeAngle(base - 3.0 * sigma)) &&
          InView(*view.profile, core::NormalizeAngle(base + 3.0 * sigma))) {
        kept.emplace_back(&reading, &view);
        break;
      }
    }
  }
  const auto sum_at = [&](double offset, int* compared) {
    double sum = 0.0;
    int count = 0;
    for (const auto& [reading, view] : kept) {
      const std::optional<double> agreement =
          AgreementAt(*reading, *view->profile,
                      core::NormalizeAngle(predicted_heading + offset + reading->bearing_rad -
                                           view->heading_rad),
                      options);
      if (!agreement) continue;
      ++count;
      sum += *agreement;
    }
    if (compared != nullptr) *compared = count;
    return sum;
  };
  int compared = 0;
  sum_at(0.0, &compared);
  match.compared = compared;
  if (compared < options.min_compared) return match;
  double best = -std::numeric_limits<double>::infinity();
  for (int k = -n; k <= n; ++k) {
    const double offset = k * options.step_rad;
    const double objective =
        sum_at(offset, nullptr) - options.prior_weight * 0.5 * (offset / sigma) * (offset / sigma);
    if (objective > best) {
      best = objective;
      match.offset_rad = offset;
    }
  }
  int compared_there = 0;
  const double sum = sum_at(match.offset_rad, &compared_there);
  match.score = compared_there > 0 ? sum / compared_there : 0.0;
  match.accepted = true;
  return match;
}

}  // namespace pirouette::localize
