#include "pirouette/robot/line_protocol.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "pirouette/robot/robot_error.h"

namespace pirouette::robot {
namespace {

using ::testing::HasSubstr;

// The line without its '\n', as a reader hands it to the parsers.
std::string Chomp(std::string line) {
  EXPECT_FALSE(line.empty());
  EXPECT_EQ(line.back(), '\n');
  line.pop_back();
  return line;
}

TEST(LineProtocolTest, RequestsAreWrittenInDegreesAndMetres) {
  EXPECT_EQ(FormatRequest(Request::FromMove(core::Move::Turn(std::numbers::pi / 2))), "TURN 90\n");
  EXPECT_EQ(FormatRequest(Request::FromMove(core::Move::Straight(-0.25))), "MOVE -0.25\n");
  EXPECT_EQ(FormatRequest(Request::Capture()), "CAPTURE\n");
  EXPECT_EQ(FormatRequest(Request::Odometry()), "ODOM\n");
  EXPECT_EQ(FormatRequest(Request::Hello()), "HELLO pirouette-robot/1\n");
}

TEST(LineProtocolTest, RequestsRoundTripExactly) {
  for (const double radians : {0.5236, -0.5236, std::numbers::pi / 6, -3.0, 1e-12, 0.0, 12.5}) {
    const Request read =
        ParseRequest(Chomp(FormatRequest(Request::FromMove(core::Move::Turn(radians)))));
    EXPECT_EQ(read.kind, Request::Kind::kTurn);
    EXPECT_EQ(read.amount, radians);
  }
  for (const double metres : {0.1, -0.3, 1.0 / 3.0, 0.0}) {
    const Request read =
        ParseRequest(Chomp(FormatRequest(Request::FromMove(core::Move::Straight(metres)))));
    EXPECT_EQ(read.kind, Request::Kind::kMove);
    EXPECT_EQ(read.amount, metres);
  }
  EXPECT_EQ(ParseRequest("CAPTURE").kind, Request::Kind::kCapture);
  EXPECT_EQ(ParseRequest("ODOM").kind, Request::Kind::kOdometry);
  const Request hello = ParseRequest("HELLO pirouette-robot/1");
  EXPECT_EQ(hello.kind, Request::Kind::kHello);
  EXPECT_EQ(hello.version, kProtocolVersion);
}

TEST(LineProtocolTest, RequestsFromScriptsAreReadLeniently) {
  EXPECT_EQ(ParseRequest("TURN 30\r").amount, ParseDegrees("30"));
  EXPECT_NEAR(ParseDegrees("30"), std::numbers::pi / 6, 1e-15);
  EXPECT_EQ(ParseRequest("  MOVE\t+0.5  ").amount, 0.5);
  EXPECT_EQ(ParseRequest("MOVE 1e-1").amount, 0.1);
  EXPECT_EQ(ParseRequest("CAPTURE\r").kind, Request::Kind::kCapture);
}

TEST(LineProtocolTest, GarbageRequestsAreRefusedWithTheLineQuoted) {
  for (const char* line : {"", "TURN", "TURN abc", "TURN nan", "TURN inf", "MOVE 1 2", "JUMP 3",
                           "capture", "CAPTURE now", "HELLO", "MOVE 0x10"}) {
    EXPECT_THROW(ParseRequest(line), RobotError) << line;
  }
  try {
    ParseRequest("JUMP\x01 3");
    FAIL();
  } catch (const RobotError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'JUMP\\x01 3'"));
    EXPECT_THAT(e.what(), HasSubstr("TURN <degrees>"));
  }
}

TEST(LineProtocolTest, DegreesAreShortAndReadBackBitExactly) {
  EXPECT_EQ(FormatDegrees(0.0), "0");
  EXPECT_EQ(FormatDegrees(std::numbers::pi), "180");
  EXPECT_EQ(FormatDegrees(-std::numbers::pi / 2), "-90");
  EXPECT_EQ(ParseDegrees("180"), std::numbers::pi);
  // π/6 as a double is not exactly 30°, and says so.
  EXPECT_EQ(FormatDegrees(std::numbers::pi / 6), "29.999999999999997");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-10.0, 10.0);
  std::uniform_real_distribution<double> exponent(-30.0, 3.0);
  for (int i = 0; i < 5000; ++i) {
    const double radians = i % 2 == 0 ? angle(rng) : std::pow(10.0, exponent(rng));
    const std::string text = FormatDegrees(radians);
    ASSERT_EQ(ParseDegrees(text), radians) << text;
    ASSERT_LE(text.size(), 24U) << text;
  }
  EXPECT_THROW(ParseDegrees("north"), RobotError);
  EXPECT_THROW(FormatDegrees(std::numeric_limits<double>::quiet_NaN()), RobotError);
}

TEST(LineProtocolTest, MoveRepliesRoundTripExactly) {
  core::MoveOutcome turn;
  turn.requested = core::Move::Turn(0.5236);
  turn.achieved = 0.5236;
  turn.odometry = core::Pose2(0.1 + 0.2, -1.0 / 3.0, 2.5);
  const std::string turn_line = FormatMoveReply(turn);
  const core::MoveOutcome turn_read = ParseMoveReply(Chomp(turn_line), turn.requested);
  EXPECT_EQ(turn_read.requested.kind, core::Move::Kind::kTurn);
  EXPECT_EQ(turn_read.requested.amount, 0.5236);
  EXPECT_EQ(turn_read.achieved, 0.5236);
  EXPECT_EQ(turn_read.odometry.x(), turn.odometry.x());
  EXPECT_EQ(turn_read.odometry.y(), turn.odometry.y());
  EXPECT_EQ(turn_read.odometry.heading(), turn.odometry.heading());
  EXPECT_FALSE(turn_read.stopped_at_contact);

  core::MoveOutcome blocked;
  blocked.requested = core::Move::Straight(0.5);
  blocked.achieved = 0.123456789;
  blocked.stopped_at_contact = true;
  blocked.odometry = core::Pose2(1.5, 0.25, -std::numbers::pi / 2);
  const std::string blocked_line = FormatMoveReply(blocked);
  EXPECT_EQ(blocked_line, "OK 0.123456789 1.5 0.25 -90 1\n");
  const core::MoveOutcome blocked_read = ParseMoveReply(Chomp(blocked_line), blocked.requested);
  EXPECT_EQ(blocked_read.achieved, 0.123456789);
  EXPECT_TRUE(blocked_read.stopped_at_contact);
  EXPECT_EQ(blocked_read.odometry.heading(), -std::numbers::pi / 2);
}

TEST(LineProtocolTest, FrameHeadersAndOdometryRoundTripExactly) {
  Frame frame;
  frame.image = core::ImageRgb8(320, 240);
  frame.odometry = core::Pose2(0.2, 0.7, 0.5236 * 3);
  frame.time_s = 12.05;
  const std::string line = FormatFrameHeader(frame);
  EXPECT_TRUE(line.starts_with("FRAME 320 240 0.2 0.7 "));
  const FrameHeader header = ParseFrameHeader(Chomp(line));
  EXPECT_EQ(header.width, 320);
  EXPECT_EQ(header.height, 240);
  EXPECT_EQ(header.ByteCount(), 320U * 240U * 3U);
  EXPECT_EQ(header.odometry.x(), 0.2);
  EXPECT_EQ(header.odometry.y(), 0.7);
  EXPECT_EQ(header.odometry.heading(), frame.odometry.heading());
  EXPECT_EQ(header.time_s, 12.05);

  const core::Pose2 pose(-0.1, 3.25, -2.9);
  const core::Pose2 read = ParseOdometryReply(Chomp(FormatOdometryReply(pose)));
  EXPECT_EQ(read.x(), pose.x());
  EXPECT_EQ(read.y(), pose.y());
  EXPECT_EQ(read.heading(), pose.heading());
}

TEST(LineProtocolTest, GarbageRepliesAreRefused) {
  const core::Move turn = core::Move::Turn(1.0);
  EXPECT_THROW(ParseMoveReply("OK 1 2 3 4", turn), RobotError);
  EXPECT_THROW(ParseMoveReply("OK 1 2 3 4 2", turn), RobotError);
  EXPECT_THROW(ParseMoveReply("YES 1 2 3 4 0", turn), RobotError);
  EXPECT_THROW(ParseMoveReply("OK a 2 3 4 0", turn), RobotError);
  EXPECT_THROW(ParseFrameHeader("FRAME -1 2 0 0 0 0"), RobotError);
  EXPECT_THROW(ParseFrameHeader("FRAME 0 2 0 0 0 0"), RobotError);
  EXPECT_THROW(ParseFrameHeader("FRAME 100000 100000 0 0 0 0"), RobotError);
  EXPECT_THROW(ParseFrameHeader("FRAME 2 2 0 0 0"), RobotError);
  EXPECT_THROW(ParseOdometryReply("OK 0 0"), RobotError);
  EXPECT_THROW(ParseOdometryReply("ERR no"), RobotError);
  EXPECT_THROW(ParseHelloReply("OK pirouette-robot/2"), RobotError);
  // Degrees beyond a double's range (fuzz/regressions/line_protocol): refused,
  // not read as an infinite heading or turn.
  EXPECT_THROW(ParseOdometryReply("OK 30 0.2 0.1e3080"), RobotError);
  EXPECT_THROW(ParseMoveReply("OK 1e4000 0 0 0 0", turn), RobotError);
  EXPECT_THROW(ParseRequest("TURN -1e4000"), RobotError);
  EXPECT_NO_THROW(ParseHelloReply("OK pirouette-robot/1\r"));
  EXPECT_EQ(ParseFrameHeader("FRAME 0 0 0 0 0 0").ByteCount(), 0U);
}

TEST(LineProtocolTest, ErrorRepliesCarryTheirMessageOnOneLine) {
  EXPECT_EQ(FormatErrorReply("motor\nstalled"), "ERR motor stalled\n");
  EXPECT_EQ(ErrorReplyMessage("ERR motor stalled\r"), "motor stalled");
  EXPECT_EQ(ErrorReplyMessage("ERR"), "(no message)");
  EXPECT_EQ(ErrorReplyMessage("OK 0 0 0"), std::nullopt);
  EXPECT_EQ(ErrorReplyMessage("ERROR"), std::nullopt);
}

TEST(LineProtocolTest, QuoteShowsUnprintableBytesAndCutsLongText) {
  EXPECT_EQ(Quote("a\tb"), "'a\\x09b'");
  EXPECT_EQ(Quote(std::string(100, 'x')), "'" + std::string(80, 'x') + "'...");
}

}  // namespace
}  // namespace pirouette::robot
