#include "pirouette/explore/goal_memory.h"

#include <algorithm>
#include <cmath>

namespace pirouette::explore {

bool GoalMemory::GaveUp(const Eigen::Vector2d& goal_world, double tolerance_m) const {
  return std::any_of(given_up_.begin(), given_up_.end(), [&](const Eigen::Vector2d& b) {
    return std::abs(b.x() - goal_world.x()) < tolerance_m &&
           std::abs(b.y() - goal_world.y()) < tolerance_m;
  });
}

}  // namespace pirouette::explore
