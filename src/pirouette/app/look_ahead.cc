#include "pirouette/app/look_ahead.h"

#include <algorithm>
#include <cmath>

#include "pirouette/core/geometry2.h"

namespace pirouette::app {

double LookAhead::LongestCheckedMove() const {
  return std::max(0.0, options_.max_range_m - options_.radius_m);
}

LookAhead::Finding LookAhead::Blocking(const core::ObstacleProfile& profile,
                                       double distance_m) const {
  const double r = options_.radius_m - options_.cell_m;
  const Eigen::Vector2d end(distance_m, 0.0);
  Finding finding;
  bool blind = false;
  for (const core::RangeReading& reading : profile.readings) {
    if (reading.kind == core::ReadingKind::kClear) continue;
    const double x = reading.range_m * std::cos(reading.bearing_rad);
    const double y = reading.range_m * std::sin(reading.bearing_rad);
    if (x <= 0.0) continue;
    if (reading.kind == core::ReadingKind::kHit) {
      // The base of an obstacle inside the swept corridor.
      const Eigen::Vector2d p(x, y);
      if (core::DistanceToSegment(p, Eigen::Vector2d::Zero(), end) < r) {
        finding.hits_robot.push_back(p);
      }
    } else if (std::abs(y) < options_.radius_m) {
      blind = true;
    }
  }
  if (!finding.hits_robot.empty()) {
    finding.verdict = LookVerdict::kBlocked;
  } else if (blind) {
    finding.verdict = LookVerdict::kBlind;
  }
  return finding;
}

double NearRange(const camera::InversePerspectiveMap& ipm) {
  double near = 0.0;
  const int v = ipm.height() - 1;
  for (int u = 0; u < ipm.width(); ++u) {
    if (const auto p = ipm.At(u, v)) near = std::max(near, static_cast<double>(p->norm()));
  }
  return near;
}

bool CorridorKnownFree(const mapping::TrinaryMap& map, const Eigen::Vector2d& from,
                       const Eigen::Vector2d& to, double radius_m) {
  const core::GridGeometry& g = map.geometry;
  const double reach = radius_m + 0.5 * g.resolution();
  const Eigen::Vector2d lo = from.cwiseMin(to) - Eigen::Vector2d(reach, reach);
  const Eigen::Vector2d hi = from.cwiseMax(to) + Eigen::Vector2d(reach, reach);
  const core::CellIndex a = g.CellOf(lo);
  const core::CellIndex b = g.CellOf(hi);
  for (int y = a.y; y <= b.y; ++y) {
    for (int x = a.x; x <= b.x; ++x) {
      const core::CellIndex c{x, y};
      if (core::DistanceToSegment(g.CellCentre(c), from, to) > reach) continue;
      if (!g.Contains(c) || map.At(c) != mapping::CellState::kFree) return false;
    }
  }
  return true;
}

}  // namespace pirouette::app
