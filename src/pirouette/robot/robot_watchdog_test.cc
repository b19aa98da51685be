#include "pirouette/robot/robot_watchdog.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <numbers>
#include <string>

#include "pirouette/robot/robot_error.h"
#include "pirouette/testing/fake_robot.h"

namespace pirouette::robot {
namespace {

using ::testing::HasSubstr;

// A FakeRobot whose replies a test bends before the watchdog sees them.
class BentRobot : public testing::FakeRobot {
 public:
  BentRobot() : FakeRobot(8, 6) {}

  core::MoveOutcome Execute(const core::Move& move) override {
    core::MoveOutcome outcome = FakeRobot::Execute(move);
    if (bend_move) bend_move(outcome);
    return outcome;
  }
  Frame Capture() override {
    Frame frame = FakeRobot::Capture();
    if (bend_frame) bend_frame(frame);
    return frame;
  }

  std::function<void(core::MoveOutcome&)> bend_move;
  std::function<void(Frame&)> bend_frame;
};

// The explorer's rhythm: a frame, a turn, a frame, a drive, `rounds` times.
void Explore(Robot& robot, int rounds) {
  for (int i = 0; i < rounds; ++i) {
    robot.Capture();
    robot.Execute(core::Move::Turn(std::numbers::pi / 6));
    robot.Capture();
    robot.Execute(core::Move::Straight(0.1));
  }
}

std::string ReasonOf(Robot& robot, int rounds) {
  try {
    Explore(robot, rounds);
  } catch (const RobotError& e) {
    return e.what();
  }
  return "";
}

TEST(RobotWatchdogTest, AWorkingRobotPassesAndAContactIsNoFault) {
  BentRobot robot;
  robot.contact_after_m = 0.0;  // every drive stops at once at contact
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_NO_THROW(Explore(watchdog, 10));
}

TEST(RobotWatchdogTest, MovesTooSmallToJudgeNeverCount) {
  BentRobot robot;
  robot.bend_move = [](core::MoveOutcome& o) { o.achieved *= 0.4; };
  RobotWatchdog watchdog(robot, "the robot");
  for (int i = 0; i < 10; ++i) {
    EXPECT_NO_THROW(watchdog.Execute(core::Move::Turn(0.003)));
    EXPECT_NO_THROW(watchdog.Execute(core::Move::Straight(0.001)));
  }
}

TEST(RobotWatchdogTest, FramesEqualAtRestAreNoFault) {
  BentRobot robot;
  core::ImageRgb8 still(8, 6);
  robot.bend_frame = [&](Frame& frame) { frame.image = still; };
  RobotWatchdog watchdog(robot, "the robot");
  for (int i = 0; i < 10; ++i) EXPECT_NO_THROW(watchdog.Capture());
}

TEST(RobotWatchdogTest, ATeleportIsAJump) {
  BentRobot robot;
  int moves = 0;
  robot.bend_move = [&](core::MoveOutcome& o) {
    if (++moves >= 3) {
      o.odometry = core::Pose2(o.odometry.x() + 1.0, o.odometry.y(), o.odometry.heading());
    }
  };
  RobotWatchdog watchdog(robot, "the robot at here");
  EXPECT_THAT(ReasonOf(watchdog, 5),
              HasSubstr("the robot at here reported odometry that jumped 1."));
}

TEST(RobotWatchdogTest, AFlippedHeadingIsAJump) {
  BentRobot robot;
  int moves = 0;
  robot.bend_move = [&](core::MoveOutcome& o) {
    if (++moves == 4) o.odometry = o.odometry * core::Pose2(0, 0, std::numbers::pi);
  };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 5), HasSubstr("heading that jumped 180°"));
}

TEST(RobotWatchdogTest, OdometryThatJumpsWhileStandingIsAJump) {
  BentRobot robot;
  robot.bend_frame = [](Frame& f) { f.odometry = core::Pose2(5.0, 5.0, 0.0); };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 1), HasSubstr("between the last move and CAPTURE"));
}

TEST(RobotWatchdogTest, AClockThatGoesBackwards) {
  BentRobot robot;
  int frames = 0;
  robot.bend_frame = [&](Frame& f) {
    if (++frames >= 3) f.time_s -= 100.0;
  };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 3), HasSubstr("its clock went backwards"));
}

TEST(RobotWatchdogTest, AFrameStampedAsTheOneBeforeAfterAMoveIsLate) {
  BentRobot robot;
  robot.bend_frame = [](Frame& f) { f.time_s = 1.0; };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 3), HasSubstr("a late frame"));
}

TEST(RobotWatchdogTest, TheSameFrameAgainAndAgainIsAFrozenCamera) {
  BentRobot robot;
  core::ImageRgb8 frozen(8, 6);
  robot.bend_frame = [&](Frame& f) { f.image = frozen; };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 3), HasSubstr("the very same frame 3 times"));
}

TEST(RobotWatchdogTest, ARobotThatDoesNotMove) {
  BentRobot robot;
  core::Pose2 stuck = robot.Odometry();
  robot.bend_move = [&](core::MoveOutcome& o) {
    o.achieved = 0.0;
    o.odometry = stuck;
  };
  robot.bend_frame = [&](Frame& f) { f.odometry = stuck; };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 3), HasSubstr("did not move: 3 moves in a row made nothing"));
}

TEST(RobotWatchdogTest, ARobotThatMovesLessThanTold) {
  BentRobot robot;
  robot.bend_move = [&](core::MoveOutcome& o) { o.achieved *= 0.25; };
  RobotWatchdog watchdog(robot, "the robot");
  EXPECT_THAT(ReasonOf(watchdog, 3), HasSubstr("moves less than it is told"));
}

}  // namespace
}  // namespace pirouette::robot
