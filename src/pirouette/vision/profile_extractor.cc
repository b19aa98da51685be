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

core::RangeReading ColumnReading(const cv::Mat1b& mask, const camera::InversePerspectiveMap& ipm,
                                 int u, double max_range_m) {
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
      const double range = Range(edge);
      return range <= max_range_m ? Reading(edge, range, core::ReadingKind::kHit)
                                  : Reading(edge, max_range_m, core::ReadingKind::kClear);
    }
    if (!here) return Reading(*below, max_range_m, core::ReadingKind::kClear);
    if (Range(*here) > max_range_m) return Reading(*here, max_range_m, core::ReadingKind::kClear);
    below = here;
  }
  return Reading(*below, max_range_m, core::ReadingKind::kClear);
}

}  // namespace

core::ObstacleProfile ExtractProfile(const cv::Mat1b& floor_mask,
                                     const camera::InversePerspectiveMap& ipm, double max_range_m) {
  assert(floor_mask.cols == ipm.width() && floor_mask.rows == ipm.height());
  core::ObstacleProfile profile;
  profile.max_range_m = max_range_m;
  profile.readings.reserve(static_cast<std::size_t>(ipm.width()));
  for (int u = 0; u < ipm.width(); ++u) {
    profile.readings.push_back(ColumnReading(floor_mask, ipm, u, max_range_m));
  }
  return profile;
}

}  // namespace pirouette::vision
