#include "pirouette/explore/moves.h"

#include <cmath>

#include "pirouette/core/angle.h"

namespace pirouette::explore {

std::vector<Eigen::Vector2d> MergeCollinear(const Eigen::Vector2d& from,
                                            const std::vector<Eigen::Vector2d>& waypoints) {
  std::vector<Eigen::Vector2d> merged;
  Eigen::Vector2d previous = from;
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    if (i + 1 < waypoints.size()) {
      const Eigen::Vector2d a = (waypoints[i] - previous).normalized();
      const Eigen::Vector2d b = (waypoints[i + 1] - waypoints[i]).normalized();
      if (a.dot(b) > kCollinearCos) continue;
    }
    merged.push_back(waypoints[i]);
    previous = waypoints[i];
  }
  return merged;
}

std::vector<core::Move> MovesAlong(const core::Pose2& world_T_robot,
                                   const std::vector<Eigen::Vector2d>& waypoints_world) {
  std::vector<Eigen::Vector2d> long_enough;
  Eigen::Vector2d from = world_T_robot.translation();
  for (const Eigen::Vector2d& to : waypoints_world) {
    if ((to - from).norm() < kMinStraightM) continue;
    long_enough.push_back(to);
    from = to;
  }
  std::vector<core::Move> moves;
  Eigen::Vector2d start = world_T_robot.translation();
  double heading = world_T_robot.heading();
  for (const Eigen::Vector2d& end : MergeCollinear(start, long_enough)) {
    const Eigen::Vector2d d = end - start;
    const double direction = std::atan2(d.y(), d.x());
    const double turn = core::NormalizeAngle(direction - heading);
    if (std::abs(turn) >= kMinTurnRad) moves.push_back(core::Move::Turn(turn));
    moves.push_back(core::Move::Straight(d.norm()));
    heading = direction;
    start = end;
  }
  return moves;
}

}  // namespace pirouette::explore
