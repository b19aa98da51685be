#include "pirouette/sim/velocity_robot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace velocity_robot_test {

constexpr double kRadius = 0.1;
constexpr double kStep = 0.02;
constexpr core::Rgb kGrey{128, 128, 128};

// A 2 × 1.5 floor with a box [1.0, 1.2] × [0.6, 0.9]; the robot, radius 0.1,
// starts at (0.5, 0.75) facing east.
World BoxWorld(core::OdometryNoise noise = {}) {
  const camera::CameraModel camera("test", 320, 240, {277.13, 277.13, 159.5, 119.5}, {},
                                   {0.11, core::DegToRad(30.0), 0.03}, {});
  std::vector<Solid> obstacles = {MakeBox({1.1, 0.75}, {0.2, 0.3}, 0.0, 0.1, kGrey)};
  return World("box", Floor{{2.0, 1.5}, kGrey, 0.0}, std::nullopt, std::move(obstacles), Light{},
               RobotSpec{core::Pose2(0.5, 0.75, 0.0), kRadius, camera, noise});
}

// Steps `seconds` of the command, then until the robot stands still.
void DriveFor(VelocityRobot& robot, double linear, double angular, double seconds) {
  for (double t = 0.0; t < seconds - 1e-9; t += kStep) robot.Step(linear, angular, kStep);
  for (int i = 0; i < 100 && robot.still_s() == 0.0; ++i) robot.Step(0.0, 0.0, kStep);
}

TEST(VelocityRobotTest, FollowsTheCommandWithinItsAcceleration) {
  const World world = BoxWorld();
  VelocityRobot robot(world, 1, {});
  robot.Step(0.3, 0.0, kStep);
  EXPECT_NEAR(robot.linear_mps(), 0.02, 1e-12);  // 1 m/s² for 20 ms
  for (int i = 0; i < 50; ++i) robot.Step(0.3, 0.0, kStep);
  EXPECT_NEAR(robot.linear_mps(), 0.3, 1e-12);
  EXPECT_EQ(robot.still_s(), 0.0);
}

TEST(VelocityRobotTest, WithoutNoiseOdometryIsTheTruth) {
  const World world = BoxWorld();
  VelocityRobot robot(world, 1, {});
  DriveFor(robot, 0.0, 1.0, 1.0);
  EXPECT_GT(robot.odometry().heading(), 0.9);
  EXPECT_NEAR(robot.true_pose().heading(), robot.odometry().heading(), 1e-12);
  EXPECT_NEAR(robot.true_pose().x(), 0.5, 1e-12);
  EXPECT_GT(robot.still_s(), 0.0);
}

TEST(VelocityRobotTest, ABiasScalesTheTrueMotionOfEachMotion) {
  const World world = BoxWorld({0.0, 0.0, 0.0, 0.1});
  VelocityRobot robot(world, 1, world.robot().odometry_noise);
  DriveFor(robot, 0.0, -1.0, 0.5);
  const double odometry = robot.odometry().heading();
  EXPECT_LT(odometry, -0.4);
  EXPECT_NEAR(robot.true_pose().heading(), 1.1 * odometry, 1e-9);
}

TEST(VelocityRobotTest, ADriveStopsAtContactAndTheWheelsStall) {
  const World world = BoxWorld();
  VelocityRobot robot(world, 1, {});
  DriveFor(robot, 0.3, 0.0, 3.0);  // 0.9 m asked; the box's face is 0.4 m ahead, less the radius
  EXPECT_TRUE(robot.in_contact());
  EXPECT_NEAR(robot.true_pose().x(), 1.0 - kRadius, 1e-6);
  EXPECT_NEAR(robot.odometry().x(), robot.true_pose().x(), 1e-9);
  // It can back away.
  DriveFor(robot, -0.2, 0.0, 0.5);
  EXPECT_FALSE(robot.in_contact());
  EXPECT_LT(robot.true_pose().x(), 0.85);
}

TEST(VelocityRobotTest, TheSameSeedAndCommandsGiveTheSameMotion) {
  const World world = BoxWorld({0.05, 0.05, 0.0, 0.0});
  VelocityRobot a(world, 7, world.robot().odometry_noise);
  VelocityRobot b(world, 7, world.robot().odometry_noise);
  DriveFor(a, 0.0, 1.0, 0.5);
  DriveFor(b, 0.0, 1.0, 0.5);
  EXPECT_EQ(a.true_pose().heading(), b.true_pose().heading());
  EXPECT_NE(a.true_pose().heading(), a.odometry().heading());
}

}  // namespace velocity_robot_test
}  // namespace pirouette::sim
