#include "pirouette/camera/range_resolution.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace pirouette::camera {
namespace {

// Rows are bisected to far below a pixel; 60 halvings of a few hundred rows.
constexpr int kBisections = 60;

// The rows of the centre column that RangeErrorAt measures at: the top one
// has floor one pixel above it too. nullopt when there is none.
struct RowInterval {
  double top = 0.0;
  double bottom = 0.0;
};

std::optional<RowInterval> MeasurableRows(const CameraModel& camera) {
  const double bottom = camera.height() - 1.0;
  if (!RangeAtRow(camera, bottom - 1.0)) return std::nullopt;
  if (RangeAtRow(camera, -1.0)) return RowInterval{0.0, bottom};
  // The horizon lies between row -1 (none) and bottom - 1 (floor): find the
  // first row whose upper neighbour still sees the floor.
  double none = -1.0;
  double floor = bottom - 1.0;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (none + floor);
    (RangeAtRow(camera, mid) ? floor : none) = mid;
  }
  const double top = std::max(0.0, floor + 1.0);
  if (top > bottom) return std::nullopt;
  return RowInterval{top, bottom};
}

RangeError ErrorAtRow(const CameraModel& camera, double row) {
  const std::optional<double> here = RangeAtRow(camera, row);
  const std::optional<double> above = RangeAtRow(camera, row - 1.0);
  const std::optional<double> below = RangeAtRow(camera, row + 1.0);
  assert(here && above && below);
  RangeError error;
  error.range_m = *here;
  error.row = row;
  error.nearer_m = std::abs(*here - *below);
  error.farther_m = std::abs(*above - *here);
  return error;
}

}  // namespace

std::optional<double> RangeAtRow(const CameraModel& camera, double row) {
  const std::optional<Eigen::Vector2d> p_robot =
      camera.FloorPoint(Eigen::Vector2d(camera.intrinsics().cx, row));
  if (!p_robot) return std::nullopt;
  return p_robot->norm();
}

std::optional<RangeInterval> MeasurableRanges(const CameraModel& camera) {
  const std::optional<RowInterval> rows = MeasurableRows(camera);
  if (!rows) return std::nullopt;
  return RangeInterval{*RangeAtRow(camera, rows->bottom), *RangeAtRow(camera, rows->top)};
}

double FloorSeenInEveryColumn(const CameraModel& camera) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int u = 0; u < camera.width(); ++u) {
    const std::optional<Eigen::Vector2d> p_robot = camera.FloorPoint(Eigen::Vector2d(u, 0.0));
    if (p_robot) nearest = std::min(nearest, p_robot->norm());
  }
  return nearest;
}

double LongRange(const CameraModel& camera, double map_range_m, double factor) {
  return std::max(map_range_m, std::min(factor * map_range_m, FloorSeenInEveryColumn(camera)));
}

std::optional<RangeError> RangeErrorAt(const CameraModel& camera, double range_m) {
  const std::optional<RowInterval> rows = MeasurableRows(camera);
  if (!rows) return std::nullopt;
  // Range falls as the row grows (down the image).
  double far_row = rows->top;
  double near_row = rows->bottom;
  if (range_m > *RangeAtRow(camera, far_row) || range_m < *RangeAtRow(camera, near_row)) {
    return std::nullopt;
  }
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (far_row + near_row);
    (*RangeAtRow(camera, mid) > range_m ? far_row : near_row) = mid;
  }
  return ErrorAtRow(camera, 0.5 * (far_row + near_row));
}

double MaxRange(const CameraModel& camera, double cell_size_m) {
  assert(cell_size_m > 0.0);
  const std::optional<RowInterval> rows = MeasurableRows(camera);
  if (!rows) return 0.0;
  const double limit = 0.5 * cell_size_m;
  // The error shrinks down the image; find the highest row still below the limit.
  if (ErrorAtRow(camera, rows->bottom).worst_m() >= limit) {
    return ErrorAtRow(camera, rows->bottom).range_m;
  }
  if (ErrorAtRow(camera, rows->top).worst_m() < limit) return ErrorAtRow(camera, rows->top).range_m;
  double coarse = rows->top;
  double fine = rows->bottom;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (coarse + fine);
    (ErrorAtRow(camera, mid).worst_m() < limit ? fine : coarse) = mid;
  }
  return ErrorAtRow(camera, fine).range_m;
}

std::vector<RangeError> RangeErrorTable(const CameraModel& camera, double step_m, double to_m) {
  assert(step_m > 0.0);
  std::vector<RangeError> table;
  const std::optional<RangeInterval> ranges = MeasurableRanges(camera);
  if (!ranges) return table;
  const double last = std::min(to_m, ranges->far_m);
  for (double k = std::ceil(ranges->near_m / step_m - 1e-9); k * step_m <= last + 1e-9; k += 1.0) {
    if (const std::optional<RangeError> error = RangeErrorAt(camera, k * step_m)) {
      table.push_back(*error);
    }
  }
  return table;
}

}  // namespace pirouette::camera
