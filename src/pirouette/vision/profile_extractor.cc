#include "pirouette/vision/profile_extractor.h"

#include <cassert>
#include <cmath>
#include <optional>

namespace pirouette::vision {
namespace {

core::RangeReading Reading(const Eigen::Vector2f& p_robot, double range_m, core::ReadingKind kind) {
  return {std::atan2(static_cast<double>(p_robot.y()), static_cast<double>(p_robot.x())), range_m,
          kind};
}

double Range(const Eigen::Vector2f& p_robot) { return static_cast<double>(p_robot.norm()); }

// The reading of a floor edge at `edge` (robot frame) found at pixel (u, v):
// a hit within range, or kClear at its range where the pixel is unresolved.
core::RangeReading EdgeReading(const Eigen::Vector2f& edge, const cv::Mat1b& unresolved, int u,
                               int v, double max_range_m) {
  const double range = Range(edge);
  if (range > max_range_m) return Reading(edge, max_range_m, core::ReadingKind::kClear);
  const bool seen_to_here = !unresolved.empty() && unresolved(v, u) != 0;
  return Reading(edge, range, seen_to_here ? core::ReadingKind::kClear : core::ReadingKind::kHit);
}

core::RangeReading ColumnReading(const cv::Mat1b& mask, const cv::Mat1b& unresolved,
                                 const camera::InversePerspectiveMap& ipm, int u,
                                 double max_range_m) {
  const int bottom = ipm.height() - 1;
  const Eigen::Vector2f bottom_point = ipm.At(u, bottom).value_or(Eigen::Vector2f::UnitX());
  int start = -1;
  for (int v = bottom; v > bottom - kBlindSearchRows && v >= 0; --v) {
    if (mask(v, u) != 0) {
      start = v;
      break;
    }
  }
  if (start < 0) {
    return Reading(bottom_point, ipm.SeesFloor(u, bottom) ? Range(bottom_point) : 0.0,
                   core::ReadingKind::kBlind);
  }
  std::optional<Eigen::Vector2f> below = ipm.At(u, start);
  if (!below) return Reading(bottom_point, max_range_m, core::ReadingKind::kClear);
  if (Range(*below) > max_range_m) return Reading(*below, max_range_m, core::ReadingKind::kClear);
  for (int v = start - 1; v >= 0; --v) {
    const std::optional<Eigen::Vector2f> here = ipm.At(u, v);
    if (mask(v, u) == 0) {
      const Eigen::Vector2f edge = here ? Eigen::Vector2f(0.5f * (*here + *below)) : *below;
      return EdgeReading(edge, unresolved, u, v, max_range_m);
    }
    if (!here) return Reading(*below, max_range_m, core::ReadingKind::kClear);
    if (Range(*here) > max_range_m) return Reading(*here, max_range_m, core::ReadingKind::kClear);
    below = here;
  }
  return Reading(*below, max_range_m, core::ReadingKind::kClear);
}

}  // namespace

core::ObstacleProfile ExtractProfile(const cv::Mat1b& floor_mask,
                                     const camera::InversePerspectiveMap& ipm, double max_range_m,
                                     const cv::Mat1b& unresolved) {
  assert(floor_mask.cols == ipm.width() && floor_mask.rows == ipm.height());
  assert(unresolved.empty() || unresolved.size() == floor_mask.size());
  core::ObstacleProfile profile;
  profile.max_range_m = max_range_m;
  profile.readings.reserve(static_cast<std::size_t>(ipm.width()));
  for (int u = 0; u < ipm.width(); ++u) {
    profile.readings.push_back(ColumnReading(floor_mask, unresolved, ipm, u, max_range_m));
  }
  return profile;
}

ProfileExtractor::ProfileExtractor(const camera::InversePerspectiveMap& ipm, double max_range_m)
    : ipm_(ipm), max_range_m_(max_range_m), first_fail_(static_cast<std::size_t>(ipm.width())) {
  const int bottom = ipm_.height() - 1;
  const auto fails = [&](int u, int v) {
    const std::optional<Eigen::Vector2f> p = ipm_.At(u, v);
    return !p || Range(*p) > max_range_m_;
  };
  for (int u = 0; u < ipm_.width(); ++u) {
    // The first failing row at or above each row, from the top down.
    int above = -1;
    std::vector<int> first_at_or_above(static_cast<std::size_t>(ipm_.height()));
    for (int v = 0; v <= bottom; ++v) {
      if (fails(u, v)) above = v;
      first_at_or_above[v] = above;
    }
    for (int k = 0; k < kBlindSearchRows; ++k) {
      const int start = bottom - k;
      if (start < 0) {
        first_fail_[u][k] = -1;
      } else if (first_at_or_above[start] == start) {
        first_fail_[u][k] = -2;
      } else {
        first_fail_[u][k] = start > 0 ? first_at_or_above[start - 1] : -1;
      }
    }
  }
}

core::ObstacleProfile ProfileExtractor::Extract(const cv::Mat1b& floor_mask,
                                                const cv::Mat1b& unresolved) const {
  CV_Assert(floor_mask.cols == ipm_.width() && floor_mask.rows == ipm_.height());
  CV_Assert(unresolved.empty() || unresolved.size() == floor_mask.size());
  const int width = ipm_.width();
  const int height = ipm_.height();
  const int bottom = height - 1;
  core::ObstacleProfile profile;
  profile.max_range_m = max_range_m_;
  profile.readings.resize(static_cast<std::size_t>(width));

  // Each column's start (the lowest floor pixel of the bottom rows) and the
  // first failing row above it; the columns decided by these alone are read
  // at once, the others are scanned.
  std::vector<int> start(static_cast<std::size_t>(width), -1);
  std::vector<int> fail(static_cast<std::size_t>(width), -1);
  std::vector<int> end(static_cast<std::size_t>(width), -1);         // where the scan stopped
  std::vector<int> stop_head(static_cast<std::size_t>(height), -1);  // columns by fail row
  std::vector<int> stop_next(static_cast<std::size_t>(width), -1);
  for (int u = 0; u < width; ++u) {
    int k = 0;
    for (int v = bottom; v > bottom - kBlindSearchRows && v >= 0; --v, ++k) {
      if (floor_mask(v, u) != 0) {
        start[u] = v;
        break;
      }
    }
    if (start[u] < 0) {
      profile.readings[u] = ColumnReading(floor_mask, unresolved, u, -1, -1, -1);
      continue;
    }
    fail[u] = first_fail_[u][k];
    if (fail[u] == -2) {
      profile.readings[u] = ColumnReading(floor_mask, unresolved, u, start[u], -2, -1);
      start[u] = -1;  // done
    } else if (fail[u] >= 0) {
      stop_next[u] = stop_head[fail[u]];
      stop_head[fail[u]] = u;
    }
  }

  // Up the rows, all columns at once: a column stops at its first non-floor
  // row above its start, or at its failing row. Most columns stop early.
  std::vector<std::uint8_t> open(static_cast<std::size_t>(width), 0);
  std::vector<std::uint8_t> stopping(static_cast<std::size_t>(width), 0);
  int pending = 0;
  for (int u = 0; u < width; ++u) pending += start[u] > 0 ? 1 : 0;
  for (int v = bottom - 1; v >= 0 && pending > 0; --v) {
    if (v >= bottom - kBlindSearchRows) {
      for (int u = 0; u < width; ++u) open[u] = start[u] == v + 1 ? 255 : open[u];
    }
    const auto* row = floor_mask.ptr<std::uint8_t>(v);
    std::uint8_t any = 0;
    for (int u = 0; u < width; ++u) {
      stopping[u] = static_cast<std::uint8_t>(open[u] & (row[u] == 0 ? 255 : 0));
      any |= stopping[u];
    }
    if (any != 0) {
      for (int u = 0; u < width; ++u) {
        if (stopping[u] == 0) continue;
        end[u] = v;
        open[u] = 0;
        --pending;
      }
    }
    for (int u = stop_head[v]; u >= 0; u = stop_next[u]) {
      if (open[u] == 0) continue;
      end[u] = v;
      open[u] = 0;
      --pending;
    }
  }
  for (int u = 0; u < width; ++u) {
    if (start[u] < 0) continue;
    profile.readings[u] = ColumnReading(floor_mask, unresolved, u, start[u], fail[u], end[u]);
  }
  return profile;
}

// The readings of the free ColumnReading, case by case, from where the scan
// up column u stopped: `end`, the first non-floor row above `start` or the
// first row there whose floor point is missing or beyond range (`fail`), -1
// if neither. start -1: a blind column; fail -2: the start row itself fails.
core::RangeReading ProfileExtractor::ColumnReading(const cv::Mat1b& mask,
                                                   const cv::Mat1b& unresolved, int u, int start,
                                                   int fail, int end) const {
  const int bottom = ipm_.height() - 1;
  const Eigen::Vector2f bottom_point = ipm_.At(u, bottom).value_or(Eigen::Vector2f::UnitX());
  if (start < 0) {
    return Reading(bottom_point, ipm_.SeesFloor(u, bottom) ? Range(bottom_point) : 0.0,
                   core::ReadingKind::kBlind);
  }
  if (fail == -2) {
    const std::optional<Eigen::Vector2f> below = ipm_.At(u, start);
    return below ? Reading(*below, max_range_m_, core::ReadingKind::kClear)
                 : Reading(bottom_point, max_range_m_, core::ReadingKind::kClear);
  }
  if (end < 0) return Reading(*ipm_.At(u, 0), max_range_m_, core::ReadingKind::kClear);
  const Eigen::Vector2f below = *ipm_.At(u, end + 1);
  const std::optional<Eigen::Vector2f> here = ipm_.At(u, end);
  if (mask(end, u) == 0) {
    const Eigen::Vector2f edge = here ? Eigen::Vector2f(0.5f * (*here + below)) : below;
    return EdgeReading(edge, unresolved, u, end, max_range_m_);
  }
  // end == fail: a floor pixel with no floor point, or beyond range.
  if (!here) return Reading(below, max_range_m_, core::ReadingKind::kClear);
  return Reading(*here, max_range_m_, core::ReadingKind::kClear);
}

}  // namespace pirouette::vision
