#pragma once

// A plain room for the localize tests: its geometry ray-cast exactly, and
// the obstacle profiles a 60° camera would read in it.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"

namespace pirouette::testing {

// The cell of the maps the localization tests make of the room.
inline constexpr double kRoomCellM = 0.01;

// The range from `pose` along the robot-frame bearing to the walls of a room
// [0, 2] x [0, 1.5] with a box [1.2, 1.4] x [0.5, 0.8] in it.
inline double RayCast(const core::Pose2& pose, double bearing) {
  const double a = pose.heading() + bearing;
  const Eigen::Vector2d d(std::cos(a), std::sin(a));
  const Eigen::Vector2d& o = pose.translation();
  double best = 1e9;
  const auto box = [&](double lo_x, double hi_x, double lo_y, double hi_y) {
    // Each of the four sides as a segment.
    const std::array<std::array<double, 4>, 4> sides = {{{lo_x, lo_y, hi_x, lo_y},
                                                         {hi_x, lo_y, hi_x, hi_y},
                                                         {hi_x, hi_y, lo_x, hi_y},
                                                         {lo_x, hi_y, lo_x, lo_y}}};
    for (const auto& s : sides) {
      const Eigen::Vector2d p(s[0], s[1]);
      const Eigen::Vector2d e(s[2] - s[0], s[3] - s[1]);
      const double den = d.x() * e.y() - d.y() * e.x();
      if (std::abs(den) < 1e-12) continue;
      const Eigen::Vector2d w = p - o;
      const double t = (w.x() * e.y() - w.y() * e.x()) / den;
      const double u = (w.x() * d.y() - w.y() * d.x()) / den;
      if (t > 1e-9 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
    }
  };
  box(0.0, 2.0, 0.0, 1.5);
  box(1.2, 1.4, 0.5, 0.8);
  return best;
}

// A frame seen from `pose`: a 60° view of 120 columns, out to 1.2 m.
inline core::ObstacleProfile Frame(const core::Pose2& pose) {
  core::ObstacleProfile profile;
  profile.max_range_m = 1.2;
  for (int i = 0; i < 120; ++i) {
    const double bearing = (30.0 - 0.5 * i) * std::numbers::pi / 180.0;
    const double r = RayCast(pose, bearing);
    if (r <= profile.max_range_m) {
      profile.readings.push_back({bearing, r, core::ReadingKind::kHit});
    } else {
      profile.readings.push_back({bearing, profile.max_range_m, core::ReadingKind::kClear});
    }
  }
  return profile;
}

}  // namespace pirouette::testing
