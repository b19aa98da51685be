#pragma once

#include <Eigen/Core>
#include <vector>

#include "pirouette/core/move.h"
#include "pirouette/core/pose2.h"

namespace pirouette::explore {

// Turns smaller than this are left out; legs shorter than this dropped.
inline constexpr double kMinTurnRad = 1e-9;
inline constexpr double kMinStraightM = 1e-9;
// Two legs are one when the cosine of the angle between them exceeds this
// (about 0.08°): a path's straight runs of coarse cells merge, its real turns
// (at least 45° on a coarse grid) never do.
inline constexpr double kCollinearCos = 1.0 - 1e-6;

// The waypoints without those in line with their neighbours, from `from`:
// waypoint i is left out when the leg to it and the leg after it point the
// same way (kCollinearCos), so that one look and one drive make a straight
// run. The last waypoint is always kept; repeated waypoints are kept (a leg
// of length zero has no direction).
std::vector<Eigen::Vector2d> MergeCollinear(const Eigen::Vector2d& from,
                                            const std::vector<Eigen::Vector2d>& waypoints);

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
