#include "pirouette/sim/faulty_robot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/testing/fake_robot.h"

namespace pirouette::sim {
namespace {

TEST(RobotFaultTest, ReadsKindAndStart) {
  EXPECT_EQ(ParseRobotFault("teleport").kind, RobotFault::Kind::kTeleport);
  EXPECT_EQ(ParseRobotFault("teleport").from, 1);
  const RobotFault fault = ParseRobotFault("half-frame@7");
  EXPECT_EQ(fault.kind, RobotFault::Kind::kHalfFrame);
  EXPECT_EQ(fault.from, 7);
  EXPECT_THROW(ParseRobotFault("gremlins"), core::InputError);
  EXPECT_THROW(ParseRobotFault("flip@0"), core::InputError);
  EXPECT_THROW(ParseRobotFault("flip@x"), core::InputError);
}

TEST(FaultyRobotTest, ATeleportShiftsOdometryFromItsRequestOn) {
  testing::FakeRobot fake(4, 3);
  FaultyRobot robot(fake, ParseRobotFault("teleport@2"));
  const core::Pose2 start = robot.Odometry();
  EXPECT_NEAR(robot.Execute(core::Move::Turn(0.5)).odometry.x(), start.x(), 1e-12);
  EXPECT_NEAR(robot.Capture().odometry.x(), start.x() + RobotFault::kTeleportM, 1e-12);
  EXPECT_NEAR(robot.Odometry().x(), start.x() + RobotFault::kTeleportM, 1e-12);
}

TEST(FaultyRobotTest, AFlipTurnsTheHeadingByPi) {
  testing::FakeRobot fake(4, 3);
  FaultyRobot robot(fake, ParseRobotFault("flip"));
  const double before = fake.Odometry().heading();
  EXPECT_NEAR(std::abs(core::NormalizeAngle(robot.Capture().odometry.heading() - before)),
              std::numbers::pi, 1e-9);
}

TEST(FaultyRobotTest, StalledAndShortMoves) {
  testing::FakeRobot fake(4, 3);
  FaultyRobot stalled(fake, ParseRobotFault("stalled"));
  const core::MoveOutcome none = stalled.Execute(core::Move::Straight(0.2));
  EXPECT_EQ(none.achieved, 0.0);
  EXPECT_EQ(none.requested.amount, 0.2);
  FaultyRobot short_moves(fake, ParseRobotFault("short-moves"));
  EXPECT_NEAR(short_moves.Execute(core::Move::Straight(0.2)).achieved,
              RobotFault::kShortFraction * 0.2, 1e-12);
}

TEST(FaultyRobotTest, LateFramesAreTheOneBeforeAndOutOfOrderOnesGoBack) {
  testing::FakeRobot fake(4, 3);
  FaultyRobot late(fake, ParseRobotFault("late@3"));
  const robot::Frame first = late.Capture();
  late.Execute(core::Move::Turn(0.5));
  const robot::Frame again = late.Capture();
  EXPECT_EQ(again.time_s, first.time_s);
  EXPECT_EQ(again.image.width(), first.image.width());

  testing::FakeRobot other(4, 3);
  FaultyRobot swapped(other, ParseRobotFault("out-of-order"));
  const robot::Frame later = swapped.Capture();
  const robot::Frame earlier = swapped.Capture();
  EXPECT_LT(earlier.time_s, later.time_s);
}

TEST(FaultyRobotTest, ClockBackAndSameFrame) {
  testing::FakeRobot fake(4, 3);
  FaultyRobot back(fake, ParseRobotFault("clock-back@2"));
  const double t = back.Capture().time_s;
  EXPECT_LT(back.Capture().time_s, t);
  testing::FakeRobot other(4, 3);
  FaultyRobot same(other, ParseRobotFault("same-frame"));
  const robot::Frame a = same.Capture();
  same.Execute(core::Move::Turn(0.5));
  const robot::Frame b = same.Capture();
  EXPECT_TRUE(std::equal(a.image.data(), a.image.data() + a.image.size_bytes(), b.image.data()));
}

}  // namespace
}  // namespace pirouette::sim
