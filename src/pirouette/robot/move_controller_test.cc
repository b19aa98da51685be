#include "pirouette/robot/move_controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pirouette::robot {
namespace {

using core::Move;

constexpr double kStep = 0.02;  // a base that reports odometry at 50 Hz

struct Result {
  double made = 0.0;         // along the move, in its unit
  double top_speed = 0.0;    // largest |command|
  double first_speed = 0.0;  // |command| of the first update
  int steps = 0;
};

// Drives an ideal base (it follows the command one step late, as a real
// base's command arrives after its odometry went out) through `move` until
// the controller says it is reached and the base is at rest.
Result Drive(const Move& move, const MotionLimits& limits = {}) {
  core::Pose2 pose(1.0, 2.0, 0.5);
  MoveController controller(move, pose, 10.0, limits);
  Velocity command;
  Result result;
  double t = 10.0;
  for (; result.steps < 10000; ++result.steps) {
    pose = pose * core::Pose2(command.linear_mps * kStep, 0.0, command.angular_rps * kStep);
    t += kStep;
    command = controller.Update(pose, t);
    const double speed = std::abs(command.linear_mps) + std::abs(command.angular_rps);
    if (result.steps == 0) result.first_speed = speed;
    result.top_speed = std::max(result.top_speed, speed);
    if (speed == 0.0) break;
  }
  result.made = controller.progress();
  return result;
}

TEST(MoveControllerTest, ATurnEndsWithinItsTolerance) {
  const MotionLimits limits;
  for (const double angle :
       {std::numbers::pi / 6, -std::numbers::pi / 6, 1.5 * std::numbers::pi, -3.0, 0.01}) {
    const Result r = Drive(Move::Turn(angle));
    EXPECT_NEAR(r.made, angle, 2.0 * limits.angle_tolerance_rad) << angle;
    EXPECT_LE(r.top_speed, limits.max_angular_rps + 1e-12);
  }
}

TEST(MoveControllerTest, ADriveEndsWithinItsTolerance) {
  const MotionLimits limits;
  for (const double distance : {0.5, -0.3, 2.0, 0.004}) {
    const Result r = Drive(Move::Straight(distance));
    EXPECT_NEAR(r.made, distance, 2.0 * limits.distance_tolerance_m) << distance;
    EXPECT_LE(r.top_speed, limits.max_linear_mps + 1e-12);
  }
}

TEST(MoveControllerTest, RampsUpFromRestAndCruises) {
  const MotionLimits limits;
  const Result r = Drive(Move::Straight(1.0));
  EXPECT_LE(r.first_speed,
            std::max(limits.min_linear_mps, limits.linear_accel_mps2 * kStep) + 1e-9);
  EXPECT_NEAR(r.top_speed, limits.max_linear_mps, 1e-12);
  // 1 m at 0.2 m/s with 0.4 s of ramps at each end: a little over 5 s.
  EXPECT_GT(r.steps * kStep, 5.0);
  EXPECT_LT(r.steps * kStep, 6.5);
}

TEST(MoveControllerTest, AMoveSmallerThanTheToleranceIsStillMade) {
  // At least half of it, and past it by no more than one odometry period at
  // the slowest speed.
  const MotionLimits limits;
  const Result turn = Drive(Move::Turn(0.001));
  EXPECT_GE(turn.made, 0.0005);
  EXPECT_LE(turn.made, 0.001 + limits.min_angular_rps * kStep + 1e-12);
  const Result drive = Drive(Move::Straight(0.0026));
  EXPECT_GE(drive.made, 0.0013);
  EXPECT_LE(drive.made, 0.0026 + limits.min_linear_mps * kStep + 1e-12);
  EXPECT_EQ(Drive(Move::Straight(0.0)).top_speed, 0.0);
}

TEST(MoveControllerTest, ProgressOfADriveIsAlongItsStartHeading) {
  const core::Pose2 start(0.0, 0.0, 0.0);
  MoveController controller(Move::Straight(1.0), start, 0.0);
  controller.Update(core::Pose2(0.4, 0.3, 0.1), 1.0);
  EXPECT_NEAR(controller.progress(), 0.4, 1e-12);
  EXPECT_FALSE(controller.reached());
}

}  // namespace
}  // namespace pirouette::robot
