#include "pirouette/sim/sim_robot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace {

using core::Move;
using core::MoveOutcome;

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.1;
constexpr core::Rgb kGrey{128, 128, 128};

camera::CameraModel BoxWorldCamera() {
  return camera::CameraModel("test", 320, 240, {277.13, 277.13, 159.5, 119.5}, {},
                             {0.11, core::DegToRad(30.0), 0.03}, {});
}

// A 2 × 1.5 floor with a box [1.0, 1.2] × [0.6, 0.9]; the robot, radius 0.1,
// starts at (0.5, 0.75) facing east.
World BoxWorld(core::OdometryNoise noise = {},
               const core::Pose2& start = core::Pose2(0.5, 0.75, 0.0)) {
  std::vector<Solid> obstacles = {MakeBox({1.1, 0.75}, {0.2, 0.3}, 0.0, 0.1, kGrey)};
  return World("box", Floor{{2.0, 1.5}, kGrey, 0.0}, std::nullopt, std::move(obstacles), Light{},
               RobotSpec{start, kRadius, BoxWorldCamera(), noise});
}

// A cluttered 3 × 2 world with walls and every kind of solid.
World ClutteredWorld() {
  std::vector<Solid> obstacles = {
      MakeBox({0.8, 0.5}, {0.3, 0.2}, core::DegToRad(30.0), 0.1, kGrey),
      MakeCylinder({2.2, 1.4}, 0.15, 0.1, kGrey),
      MakeWall({1.5, 0.0}, {1.5, 0.9}, 0.04, 0.1, kGrey),
      MakePrism({{0.3, 1.2}, {0.9, 1.2}, {0.9, 1.4}, {0.5, 1.4}, {0.5, 1.8}, {0.3, 1.8}}, 0.1,
                kGrey),
      MakeBox({2.5, 0.5}, {0.2, 0.2}, core::DegToRad(45.0), 0.1, kGrey),
  };
  return World("cluttered", Floor{{3.0, 2.0}, kGrey, 0.0}, BoundaryWalls{0.1, 0.05, kGrey},
               std::move(obstacles), Light{},
               RobotSpec{core::Pose2(1.0, 1.0, 0.0), kRadius, BoxWorldCamera(), {}});
}

SimRobot::View EmptyView() {
  return [](const core::Pose2&) { return core::ImageRgb8(); };
}

void ExpectPose(const core::Pose2& actual, double x, double y, double heading,
                double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x(), x, tolerance);
  EXPECT_NEAR(actual.y(), y, tolerance);
  EXPECT_NEAR(core::NormalizeAngle(actual.heading() - heading), 0.0, tolerance);
}

// Sphere tracing on World::Clearance, as a reference for where a straight
// drive of `length` along `u` stops: the distance made.
double SphereTrace(const World& world, const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                   double length) {
  double s = 0.0;
  for (int i = 0; i < 10'000'000 && s < length; ++i) {
    const double gap = world.Clearance(origin + s * u) - kRadius;
    if (gap < 1e-11) break;
    s = std::min(length, s + gap);
  }
  return s;
}

TEST(SimRobotTest, StartsAtTheStartPose) {
  const World world = BoxWorld();
  const SimRobot robot(world, 1, EmptyView());
  ExpectPose(robot.TruePose(), 0.5, 0.75, 0.0, 0.0);
  ExpectPose(robot.Odometry(), 0.5, 0.75, 0.0, 0.0);
}

TEST(SimRobotTest, TurnsAndStraightMovesWithoutNoise) {
  const World world = BoxWorld();
  SimRobot robot(world, 1, EmptyView());

  MoveOutcome outcome = robot.Execute(Move::Turn(kPi / 2.0));
  EXPECT_EQ(outcome.requested.kind, Move::Kind::kTurn);
  EXPECT_EQ(outcome.achieved, kPi / 2.0);
  EXPECT_FALSE(outcome.stopped_at_contact);
  ExpectPose(robot.TruePose(), 0.5, 0.75, kPi / 2.0);

  outcome = robot.Execute(Move::Straight(0.3));
  EXPECT_EQ(outcome.achieved, 0.3);
  EXPECT_FALSE(outcome.stopped_at_contact);
  ExpectPose(robot.TruePose(), 0.5, 1.05, kPi / 2.0);
  ExpectPose(robot.Odometry(), 0.5, 1.05, kPi / 2.0);
  ExpectPose(outcome.odometry, 0.5, 1.05, kPi / 2.0);

  robot.Execute(Move::Turn(3.0 * kPi / 4.0));  // now facing south-west
  outcome = robot.Execute(Move::Straight(0.2 * std::numbers::sqrt2));
  ExpectPose(robot.TruePose(), 0.3, 0.85, -3.0 * kPi / 4.0);
  ExpectPose(robot.Odometry(), 0.3, 0.85, -3.0 * kPi / 4.0);
}

TEST(SimRobotTest, BackwardMovesDriveAgainstTheHeading) {
  const World world = BoxWorld();
  SimRobot robot(world, 1, EmptyView());
  const MoveOutcome outcome = robot.Execute(Move::Straight(-0.2));
  EXPECT_EQ(outcome.achieved, -0.2);
  EXPECT_FALSE(outcome.stopped_at_contact);
  ExpectPose(robot.TruePose(), 0.3, 0.75, 0.0);
  ExpectPose(robot.Odometry(), 0.3, 0.75, 0.0);

  // Backwards into the floor's west edge: the disc stops at x = radius.
  const MoveOutcome blocked = robot.Execute(Move::Straight(-1.0));
  EXPECT_TRUE(blocked.stopped_at_contact);
  EXPECT_NEAR(blocked.achieved, -0.2, 1e-12);
  ExpectPose(robot.TruePose(), kRadius, 0.75, 0.0);
  ExpectPose(robot.Odometry(), kRadius, 0.75, 0.0);
}

TEST(SimRobotTest, StopsWithTheDiscTouchingAnObstacle) {
  const World world = BoxWorld();
  SimRobot robot(world, 1, EmptyView());
  const MoveOutcome outcome = robot.Execute(Move::Straight(1.0));
  EXPECT_TRUE(outcome.stopped_at_contact);
  // The box's west face is at x = 1.0: the centre stops at 0.9, 0.4 on.
  EXPECT_NEAR(outcome.achieved, 0.4, 1e-12);
  ExpectPose(robot.TruePose(), 0.9, 0.75, 0.0);
  ExpectPose(robot.Odometry(), 0.9, 0.75, 0.0);
  EXPECT_NEAR(world.Clearance(robot.TruePose().translation()), kRadius, 1e-9);

  // Pushing on moves nothing.
  const MoveOutcome again = robot.Execute(Move::Straight(0.1));
  EXPECT_TRUE(again.stopped_at_contact);
  EXPECT_NEAR(again.achieved, 0.0, 1e-8);
  ExpectPose(robot.TruePose(), 0.9, 0.75, 0.0, 1e-8);
}

TEST(SimRobotTest, LeavesAContactBackwardsOrTurnedAway) {
  const World world = BoxWorld();
  SimRobot robot(world, 1, EmptyView());
  robot.Execute(Move::Straight(1.0));
  ASSERT_NEAR(robot.TruePose().x(), 0.9, 1e-12);

  MoveOutcome outcome = robot.Execute(Move::Straight(-0.1));
  EXPECT_FALSE(outcome.stopped_at_contact);
  EXPECT_EQ(outcome.achieved, -0.1);
  ExpectPose(robot.TruePose(), 0.8, 0.75, 0.0);

  robot.Execute(Move::Straight(1.0));  // back into contact
  robot.Execute(Move::Turn(kPi));
  outcome = robot.Execute(Move::Straight(0.3));
  EXPECT_FALSE(outcome.stopped_at_contact);
  ExpectPose(robot.TruePose(), 0.6, 0.75, kPi);
}

TEST(SimRobotTest, SlidesAlongAFaceItTouches) {
  const World world = BoxWorld();
  SimRobot robot(world, 1, EmptyView());
  robot.Execute(Move::Straight(1.0));
  // North along the box's west face, past its corner (1.0, 0.9).
  robot.Execute(Move::Turn(kPi / 2.0));
  const MoveOutcome outcome = robot.Execute(Move::Straight(0.5));
  EXPECT_FALSE(outcome.stopped_at_contact);
  ExpectPose(robot.TruePose(), 0.9, 1.25, kPi / 2.0);
}

TEST(SimRobotTest, StopsAtACylinderOffItsAxis) {
  std::vector<Solid> obstacles = {MakeCylinder({1.5, 0.75}, 0.1, 0.1, kGrey)};
  const World world("cylinder", Floor{{2.0, 1.5}, kGrey, 0.0}, std::nullopt, std::move(obstacles),
                    Light{}, RobotSpec{core::Pose2(0.5, 0.8, 0.0), kRadius, BoxWorldCamera(), {}});
  SimRobot robot(world, 1, EmptyView());
  const MoveOutcome outcome = robot.Execute(Move::Straight(2.0));
  EXPECT_TRUE(outcome.stopped_at_contact);
  // The centres are 0.2 apart at contact: 0.05 across, so sqrt(0.04 - 0.0025) along.
  const double x = 1.5 - std::sqrt(0.0375);
  EXPECT_NEAR(outcome.achieved, x - 0.5, 1e-12);
  ExpectPose(robot.TruePose(), x, 0.8, 0.0);
  EXPECT_NEAR(world.Clearance(robot.TruePose().translation()), kRadius, 1e-9);
}

TEST(SimRobotTest, ContactsAgreeWithSphereTracingOnClearance) {
  const World world = ClutteredWorld();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(0.0, 3.0);
  std::uniform_real_distribution<double> y(0.0, 2.0);
  std::uniform_real_distribution<double> heading(-kPi, kPi);
  int contacts = 0;
  int trials = 0;
  while (trials < 300) {
    const core::Pose2 start(x(rng), y(rng), heading(rng));
    if (world.Clearance(start.translation()) < kRadius + 0.01) continue;
    ++trials;
    const World world_here("here", world.floor(), world.walls(), world.obstacles(), Light{},
                           RobotSpec{start, kRadius, BoxWorldCamera(), {}});
    SimRobot robot(world_here, 1, EmptyView());
    const double length = 1.5;
    const MoveOutcome outcome = robot.Execute(Move::Straight(length));
    const double expected = SphereTrace(world_here, start.translation(), start.Direction(), length);
    EXPECT_NEAR(outcome.achieved, expected, 1e-7);
    EXPECT_EQ(outcome.stopped_at_contact, expected < length);
    const double clearance = world_here.Clearance(robot.TruePose().translation());
    EXPECT_GE(clearance, kRadius - 1e-9);
    if (outcome.stopped_at_contact) {
      ++contacts;
      EXPECT_NEAR(clearance, kRadius, 1e-9);
      // Then drive on in a few directions: never into anything.
      for (const double turn : {kPi / 2.0, kPi / 3.0, kPi / 2.0, 2.0 * kPi / 3.0}) {
        robot.Execute(Move::Turn(turn));
        robot.Execute(Move::Straight(0.7));
        EXPECT_GE(world_here.Clearance(robot.TruePose().translation()), kRadius - 1e-9);
      }
    }
  }
  EXPECT_GT(contacts, 50);
}

TEST(SimRobotTest, ContactWithNoiseReportsTheEncoderDistance) {
  const World world = BoxWorld({0.1, 0.0});
  SimRobot robot(world, 3, EmptyView());
  const MoveOutcome outcome = robot.Execute(Move::Straight(1.0));
  ASSERT_TRUE(outcome.stopped_at_contact);
  ExpectPose(robot.TruePose(), 0.9, 0.75, 0.0);
  // The encoders measure the true 0.4 m divided by this move's (1 + ε_t), ε_t ≠ 0.
  EXPECT_NE(outcome.achieved, 0.4);
  EXPECT_NEAR(outcome.achieved, 0.4, 0.4 * 0.5);
  EXPECT_NEAR(robot.Odometry().x(), 0.5 + outcome.achieved, 1e-12);
}

// Wheels that drift one way: the body moves and turns by the bias more than
// the encoders say, every time.
TEST(SimRobotTest, BiasesScaleEveryMoveTheSameWay) {
  core::OdometryNoise noise;
  noise.translation_bias = 0.02;
  noise.rotation_bias = -0.05;
  const World world = BoxWorld(noise, core::Pose2(0.3, 0.3, 0.0));
  SimRobot robot(world, 1, EmptyView());
  robot.Execute(Move::Straight(0.2));
  ExpectPose(robot.TruePose(), 0.3 + 0.2 * 1.02, 0.3, 0.0);
  ExpectPose(robot.Odometry(), 0.5, 0.3, 0.0);
  robot.Execute(Move::Turn(1.0));
  EXPECT_NEAR(robot.TruePose().heading(), 0.95, 1e-12);
  EXPECT_NEAR(robot.Odometry().heading(), 1.0, 1e-12);
  // The world file's noise can be overridden.
  SimRobot exact(world, 1, EmptyView(), core::OdometryNoise{});
  exact.Execute(Move::Straight(0.2));
  ExpectPose(exact.TruePose(), 0.5, 0.3, 0.0);
}

TEST(SimRobotTest, TranslationNoiseStatistics) {
  constexpr int kMoves = 2000;
  constexpr double kSigma = 0.05;
  const World world = BoxWorld({kSigma, 0.0}, core::Pose2(1.0, 0.3, 0.0));
  SimRobot robot(world, 42, EmptyView());
  double sum = 0.0;
  double sum_squares = 0.0;
  for (int i = 0; i < kMoves; ++i) {
    const double command = i % 2 == 0 ? 0.1 : -0.1;  // back and forth, clear of everything
    const Eigen::Vector2d before = robot.TruePose().translation();
    const core::Pose2 odometry_before = robot.Odometry();
    const MoveOutcome outcome = robot.Execute(Move::Straight(command));
    ASSERT_FALSE(outcome.stopped_at_contact);
    EXPECT_EQ(outcome.achieved, command);  // odometry reports the command
    EXPECT_NEAR(robot.Odometry().x() - odometry_before.x(), command, 1e-12);
    const double ratio = (robot.TruePose().translation() - before).norm() / 0.1;
    sum += ratio;
    sum_squares += ratio * ratio;
  }
  const double mean = sum / kMoves;
  const double std_dev = std::sqrt((sum_squares - kMoves * mean * mean) / (kMoves - 1));
  EXPECT_NEAR(mean, 1.0, 3.0 * kSigma / std::sqrt(kMoves));
  EXPECT_NEAR(std_dev, kSigma, 0.1 * kSigma);
  EXPECT_EQ(robot.TruePose().heading(), 0.0);  // no rotation noise
}

TEST(SimRobotTest, RotationNoiseStatistics) {
  constexpr int kTurns = 2000;
  constexpr double kSigma = 0.05;
  constexpr double kTurn = 0.5;
  const World world = BoxWorld({0.0, kSigma});
  SimRobot robot(world, 43, EmptyView());
  double sum = 0.0;
  double sum_squares = 0.0;
  for (int i = 0; i < kTurns; ++i) {
    const double command = i % 2 == 0 ? kTurn : -kTurn;
    const double before = robot.TruePose().heading();
    const double odometry_before = robot.Odometry().heading();
    const MoveOutcome outcome = robot.Execute(Move::Turn(command));
    EXPECT_EQ(outcome.achieved, command);
    EXPECT_NEAR(core::NormalizeAngle(robot.Odometry().heading() - odometry_before), command, 1e-12);
    const double ratio = core::NormalizeAngle(robot.TruePose().heading() - before) / command;
    sum += ratio;
    sum_squares += ratio * ratio;
  }
  const double mean = sum / kTurns;
  const double std_dev = std::sqrt((sum_squares - kTurns * mean * mean) / (kTurns - 1));
  EXPECT_NEAR(mean, 1.0, 3.0 * kSigma / std::sqrt(kTurns));
  EXPECT_NEAR(std_dev, kSigma, 0.1 * kSigma);
  // Turning on the spot never moves the centre.
  ExpectPose(robot.TruePose(), 0.5, 0.75, robot.TruePose().heading(), 0.0);
}

std::vector<core::Pose2> Trajectory(const World& world, std::uint64_t seed) {
  SimRobot robot(world, seed, EmptyView());
  std::vector<core::Pose2> poses;
  for (int i = 0; i < 20; ++i) {
    robot.Execute(Move::Turn(i % 2 == 0 ? 0.4 : -0.4));
    robot.Execute(Move::Straight(i % 2 == 0 ? 0.05 : -0.05));
    poses.push_back(robot.TruePose());
  }
  return poses;
}

TEST(SimRobotTest, SameSeedSameTrajectoryOtherSeedOther) {
  const World world = BoxWorld({0.05, 0.05});
  const std::vector<core::Pose2> a = Trajectory(world, 5);
  const std::vector<core::Pose2> b = Trajectory(world, 5);
  const std::vector<core::Pose2> c = Trajectory(world, 6);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x(), b[i].x());
    EXPECT_EQ(a[i].y(), b[i].y());
    EXPECT_EQ(a[i].heading(), b[i].heading());
  }
  EXPECT_NE(a.back().x(), c.back().x());
  EXPECT_NE(a.back().heading(), c.back().heading());
}

TEST(SimRobotTest, CaptureRendersTheTruePoseAndStampsTheOdometryAndTime) {
  const World world = BoxWorld({0.05, 0.05});
  std::vector<core::Pose2> viewed;
  SimRobot robot(world, 9, [&viewed](const core::Pose2& world_T_robot) {
    viewed.push_back(world_T_robot);
    return core::ImageRgb8(4, 3);
  });
  robot::Frame frame = robot.Capture();
  EXPECT_EQ(frame.image.width(), 4);
  EXPECT_EQ(frame.image.height(), 3);
  EXPECT_EQ(frame.time_s, 0.0);
  ExpectPose(frame.odometry, 0.5, 0.75, 0.0, 0.0);

  robot.Execute(Move::Turn(kPi / 2.0));
  robot.Execute(Move::Straight(0.1));
  frame = robot.Capture();
  ASSERT_EQ(viewed.size(), 2u);
  ExpectPose(viewed[1], robot.TruePose().x(), robot.TruePose().y(), robot.TruePose().heading(),
             0.0);
  ExpectPose(frame.odometry, robot.Odometry().x(), robot.Odometry().y(), robot.Odometry().heading(),
             0.0);
  // 0.05 s for the first frame, the true turn at 90°/s, the true drive at 0.1 m/s.
  const double turned = std::abs(core::NormalizeAngle(robot.TruePose().heading()));
  const double driven = (robot.TruePose().translation() - Eigen::Vector2d(0.5, 0.75)).norm();
  EXPECT_NEAR(frame.time_s, 0.05 + turned / (kPi / 2.0) + driven / 0.1, 1e-12);
  EXPECT_NEAR(robot.Capture().time_s, frame.time_s + 0.05, 1e-12);
}

TEST(SimRobotTest, NullViewGivesEmptyImages) {
  const World world = BoxWorld();
  SimRobot robot(world, 1, nullptr);
  EXPECT_TRUE(robot.Capture().image.empty());
}

}  // namespace
}  // namespace pirouette::sim
