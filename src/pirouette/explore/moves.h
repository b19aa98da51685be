#pragma once

#include <Eigen/Core>
#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/robot/robot.h"

namespace pirouette::explore {

// Turns smaller than this are left out; legs shorter than this dropped.
// Legs whose directions differ by less than kCollinearRad are one leg.
inline constexpr double kMinTurnRad = 1e-9;
inline constexpr double kMinStraightM = 1e-9;
inline constexpr double kCollinearRad = 1e-6;

// The piecewise-linear motion along a path (Taylor, Geva & Boles 2005, §4:
// the robot only turns on the spot and drives straight): from the robot's
// pose, for each leg a turn to face it (radians in (-π, π], left out when
// under `kMinTurnRad`) then a straight drive (metres). Consecutive legs in
// the same direction (within kCollinearRad) are merged into one drive, and
// legs shorter than kMinStraightM are dropped. `waypoints_world` excludes the
// robot's own position.
std::vector<core::Move> MovesAlong(const core::Pose2& world_T_robot,
                                   const std::vector<Eigen::Vector2d>& waypoints_world);

}  // namespace pirouette::explore
