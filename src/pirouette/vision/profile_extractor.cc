#include "pirouette/vision/profile_extractor.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>
#include <utility>

namespace pirouette::vision {
namespace {

core::RangeReading Reading(const Eigen::Vector2f& p_robot, double range_m, core::ReadingKind kind) {
  return {std::atan2(static_cast<double>(p_robot.y()), static_cast<double>(p_robot.x())), range_m,
          kind};
}

double Range(const Eigen::Vector2f& p_robot) { return static_cast<double>(p_robot.norm()); }

// Whether pixel (u, v) is resolved: `unresolved` (empty: all are) does not
// mark it.
bool Resolved(const cv::Mat1b& unresolved, int u, int v) {
  return unresolved.empty() || unresolved(v, u) == 0;
}

// The reading of a floor edge at `edge` (robot frame) found at pixel (u, v):
// a hit within range, or kClear at its range where the pixel is unresolved.
core::RangeReading EdgeReading(const Eigen::Vector2f& edge, const cv::Mat1b& unresolved, int u,
                               int v, double max_range_m) {
  const double range = Range(edge);
  if (range > max_range_m) return Reading(edge, max_range_m, core::ReadingKind::kClear);
  return Reading(edge, range,
                 Resolved(unresolved, u, v) ? core::ReadingKind::kHit : core::ReadingKind::kClear);
}

// Where a walk down the world's vertical from pixel (u, v), not floor,
// through pixels that are not floor ends.
struct SideWalk {
  int rows = 0;         // rows walked down through pixels that are not floor
  bool bottom = false;  // still on them at the view's bottom row
  int u = 0;            // the last pixel not floor (at row v + rows)
  int floor_u = -1;     // the floor pixel the vertical meets on the next row (-1:
                        // the walk stopped short of the floor)
};

// Walks down the world's vertical from pixel (u, v) (not floor) while the
// pixel it passes through, or one beside it, is not floor: a column that
// meets an obstacle above its base walks down the obstacle's side to its
// foot. The pixels beside count because the silhouette of a vertical edge
// runs along the vertical, and a walk that kept to the nearest pixel would
// step off the obstacle onto the floor beside it by rounding, or where a
// segmented mask's edge is a pixel ragged (keeping to the two pixels either
// side of the vertical halved the maps' gain in generated mazes).
SideWalk WalkDown(const cv::Mat1b& mask, const VerticalDirectionField& vertical, int u, int v) {
  // A vertical that runs this little up the image (under a tenth of a pixel
  // a pixel) is not followed: it would step across many columns a row.
  constexpr float kMinRise = 0.1f;
  SideWalk walk{0, false, u, -1};
  auto across = static_cast<float>(u);  // where the vertical is, in columns
  for (int down = v + 1;; ++down) {
    const cv::Vec2f up = vertical.At(walk.u, down - 1);
    if (!(up[1] < -kMinRise)) return walk;
    across += up[0] / up[1];  // one row down the vertical
    if (down >= mask.rows) {
      walk.bottom = true;
      return walk;
    }
    const int nearest = std::clamp(static_cast<int>(std::lround(across)), 0, mask.cols - 1);
    int on = -1;
    for (const int c : {nearest, nearest - 1, nearest + 1}) {
      if (c >= 0 && c < mask.cols && mask(down, c) == 0) {
        on = c;
        break;
      }
    }
    if (on < 0) {
      walk.floor_u = nearest;
      return walk;
    }
    walk.u = on;
    ++walk.rows;
  }
}

// The reading of the floor's edge in column u, ended by pixel (u, v) (not
// floor) above `below`, the floor point of the floor pixel under it: see
// ExtractProfile for what `vertical` changes, and the foot it adds to `feet`.
core::RangeReading ObstacleReading(const cv::Mat1b& mask, const cv::Mat1b& unresolved,
                                   const camera::InversePerspectiveMap& ipm,
                                   const VerticalDirectionField* vertical, int u, int v,
                                   const Eigen::Vector2f& below, double max_range_m,
                                   std::vector<core::RangeReading>& feet) {
  // (core::kMinSideRows: a base line sloping across the columns lets the
  // walk slide a row or two along it, and that is still the base.)
  const std::optional<Eigen::Vector2f> here = ipm.At(u, v);
  const Eigen::Vector2f edge = here ? Eigen::Vector2f(0.5f * (*here + below)) : below;
  if (vertical == nullptr || !Resolved(unresolved, u, v)) {
    return EdgeReading(edge, unresolved, u, v, max_range_m);
  }
  const SideWalk walk = WalkDown(mask, *vertical, u, v);
  if (walk.rows < core::kMinSideRows && !walk.bottom) {
    return EdgeReading(edge, unresolved, u, v, max_range_m);
  }
  const int foot_v = v + walk.rows;
  if (walk.floor_u >= 0 && Resolved(unresolved, walk.u, foot_v)) {
    const std::optional<Eigen::Vector2f> side = ipm.At(walk.u, foot_v);
    const std::optional<Eigen::Vector2f> floor = ipm.At(walk.floor_u, foot_v + 1);
    if (side && floor) {
      const Eigen::Vector2f foot = 0.5f * (*side + *floor);
      if (Range(foot) <= max_range_m) {
        feet.push_back(Reading(foot, Range(foot), core::ReadingKind::kHit));
      }
    }
  }
  return Reading(edge, std::min(Range(edge), max_range_m), core::ReadingKind::kClear);
}

core::RangeReading ColumnReading(const cv::Mat1b& mask, const cv::Mat1b& unresolved,
                                 const camera::InversePerspectiveMap& ipm,
                                 const VerticalDirectionField* vertical, int u, double max_range_m,
                                 std::vector<core::RangeReading>& feet) {
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
      return ObstacleReading(mask, unresolved, ipm, vertical, u, v, *below, max_range_m, feet);
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
                                     const cv::Mat1b& unresolved,
                                     const VerticalDirectionField* vertical) {
  assert(floor_mask.cols == ipm.width() && floor_mask.rows == ipm.height());
  assert(unresolved.empty() || unresolved.size() == floor_mask.size());
  assert(vertical == nullptr ||
         (vertical->width() == ipm.width() && vertical->height() == ipm.height()));
  core::ObstacleProfile profile;
  profile.max_range_m = max_range_m;
  profile.readings.reserve(static_cast<std::size_t>(ipm.width()));
  for (int u = 0; u < ipm.width(); ++u) {
    profile.readings.push_back(
        ColumnReading(floor_mask, unresolved, ipm, vertical, u, max_range_m, profile.feet));
  }
  return profile;
}

ProfileExtractor::ProfileExtractor(const camera::InversePerspectiveMap& ipm, double max_range_m,
                                   std::optional<VerticalDirectionField> vertical)
    : ipm_(ipm),
      max_range_m_(max_range_m),
      vertical_(std::move(vertical)),
      first_fail_(static_cast<std::size_t>(ipm.width())) {
  CV_Assert(!vertical_ ||
            (vertical_->width() == ipm_.width() && vertical_->height() == ipm_.height()));
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
      profile.readings[u] = ColumnReading(floor_mask, unresolved, u, -1, -1, -1, profile.feet);
      continue;
    }
    fail[u] = first_fail_[u][k];
    if (fail[u] == -2) {
      profile.readings[u] =
          ColumnReading(floor_mask, unresolved, u, start[u], -2, -1, profile.feet);
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
    profile.readings[u] =
        ColumnReading(floor_mask, unresolved, u, start[u], fail[u], end[u], profile.feet);
  }
  return profile;
}

// The readings of the free ColumnReading, case by case, from where the scan
// up column u stopped: `end`, the first non-floor row above `start` or the
// first row there whose floor point is missing or beyond range (`fail`), -1
// if neither. start -1: a blind column; fail -2: the start row itself fails.
core::RangeReading ProfileExtractor::ColumnReading(const cv::Mat1b& mask,
                                                   const cv::Mat1b& unresolved, int u, int start,
                                                   int fail, int end,
                                                   std::vector<core::RangeReading>& feet) const {
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
    return ObstacleReading(mask, unresolved, ipm_, vertical_ ? &*vertical_ : nullptr, u, end, below,
                           max_range_m_, feet);
  }
  // end == fail: a floor pixel with no floor point, or beyond range.
  if (!here) return Reading(below, max_range_m_, core::ReadingKind::kClear);
  return Reading(*here, max_range_m_, core::ReadingKind::kClear);
}

}  // namespace pirouette::vision
