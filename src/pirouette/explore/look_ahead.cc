#include "pirouette/explore/look_ahead.h"

#include <algorithm>
#include <cmath>

#include "pirouette/core/geometry2.h"

namespace pirouette::explore {

double LookAhead::LongestCheckedMove() const {
  return std::max(0.0, options_.max_range_m - options_.radius_m);
}

LookAhead::Finding LookAhead::Blocking(const core::ObstacleProfile& profile,
                                       double distance_m) const {
  const double r = SweptHalfWidth();
  const Eigen::Vector2d end(distance_m, 0.0);
  Finding finding;
  // The base of an obstacle inside the swept corridor.
  const auto add_hit = [&](const core::RangeReading& hit) {
    const Eigen::Vector2d p = core::PointOf(hit);
    if (p.x() > 0.0 && core::DistanceToSegment(p, Eigen::Vector2d::Zero(), end) < r) {
      finding.hits_robot.push_back(p);
    }
  };
  bool blind = false;
  // A clear reading this much short of the max range is seen only to there.
  constexpr double kShortM = 1e-6;
  for (const core::RangeReading& reading : profile.readings) {
    const Eigen::Vector2d p = core::PointOf(reading);
    const double x = p.x();
    const double y = p.y();
    if (reading.kind == core::ReadingKind::kClear) {
      if (reading.range_m < options_.max_range_m - kShortM && x > 0.0 &&
          std::abs(y) < options_.radius_m) {
        finding.seen_m = std::min(finding.seen_m, x - options_.radius_m);
      }
      continue;
    }
    if (reading.kind == core::ReadingKind::kHit) {
      add_hit(reading);
    } else if (x > 0.0 && std::abs(y) < options_.radius_m) {
      blind = true;
    }
  }
  for (const core::RangeReading& foot : profile.feet) add_hit(foot);
  if (!finding.hits_robot.empty()) {
    finding.verdict = LookVerdict::kBlocked;
  } else if (blind) {
    finding.verdict = LookVerdict::kBlind;
  }
  return finding;
}

}  // namespace pirouette::explore
