#include "pirouette/explore/moves.h"

#include <cmath>

#include "pirouette/core/angle.h"

namespace pirouette::explore {

std::vector<core::Move> MovesAlong(const core::Pose2& world_T_robot,
                                   const std::vector<Eigen::Vector2d>& waypoints_world) {
  // The legs, merged: each a start and an end.
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> legs;
  Eigen::Vector2d from = world_T_robot.translation();
  for (const Eigen::Vector2d& to : waypoints_world) {
    if ((to - from).norm() < kMinStraightM) continue;
    if (!legs.empty()) {
      const Eigen::Vector2d a = legs.back().second - legs.back().first;
      const Eigen::Vector2d b = to - from;
      const double angle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      if (std::abs(angle) < kCollinearRad) {
        legs.back().second = to;
        from = to;
        continue;
      }
    }
    legs.emplace_back(from, to);
    from = to;
  }
  std::vector<core::Move> moves;
  double heading = world_T_robot.heading();
  for (const auto& [start, end] : legs) {
    const Eigen::Vector2d d = end - start;
    const double direction = std::atan2(d.y(), d.x());
    const double turn = core::NormalizeAngle(direction - heading);
    if (std::abs(turn) >= kMinTurnRad) moves.push_back(core::Move::Turn(turn));
    moves.push_back(core::Move::Straight(d.norm()));
    heading = direction;
  }
  return moves;
}

}  // namespace pirouette::explore
