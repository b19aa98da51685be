#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace pirouette::explore {

// What a planner remembers of its goals, explore_lite's way: the goals it gave
// up (reported unreachable, or that a pirouette where the robot stood did
// not clear), and its last plan, to tell when the robot was told to pirouette
// where it stands and the same goal comes out again.
class GoalMemory {
 public:
  // The last plan: the robot at `robot_world` was sent towards `goal_world`;
  // `stay` when the plan had no waypoints (pirouette where it stands).
  void Remember(const Eigen::Vector2d& robot_world, const Eigen::Vector2d& goal_world, bool stay) {
    last_ = Last{robot_world, goal_world, stay};
  }
  // No plan was made (nothing left to explore).
  void Forget() { last_.reset(); }

  // Whether the last plan had the robot pirouette where it still stands
  // (within `tolerance_m`).
  bool Stalled(const Eigen::Vector2d& robot_world, double tolerance_m) const {
    return last_ && last_->stay && (robot_world - last_->robot_world).norm() < tolerance_m;
  }
  // Whether `goal_world` is the last plan's goal (a coarse cell's centre,
  // exactly), or nearer than `tolerance_m` to it (a frontier's point).
  bool IsLastGoal(const Eigen::Vector2d& goal_world) const {
    return last_ && goal_world == last_->goal_world;
  }
  bool NearLastGoal(const Eigen::Vector2d& goal_world, double tolerance_m) const {
    return last_ && (goal_world - last_->goal_world).norm() < tolerance_m;
  }

  void GiveUp(const Eigen::Vector2d& goal_world) { given_up_.push_back(goal_world); }
  // The goals given up, in order.
  const std::vector<Eigen::Vector2d>& given_up() const { return given_up_; }
  // Whether a goal given up lies within `tolerance_m` of `goal_world` along
  // both axes.
  bool GaveUp(const Eigen::Vector2d& goal_world, double tolerance_m) const;

 private:
  struct Last {
    Eigen::Vector2d robot_world;
    Eigen::Vector2d goal_world;
    bool stay;
  };
  std::vector<Eigen::Vector2d> given_up_;
  std::optional<Last> last_;
};

}  // namespace pirouette::explore
