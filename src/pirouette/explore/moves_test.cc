#include "pirouette/explore/moves.h"

#include <gtest/gtest.h>

#include <numbers>

namespace pirouette::explore {
namespace {

using core::Move;
constexpr double kPi = std::numbers::pi;

void ExpectMove(const Move& move, Move::Kind kind, double amount) {
  EXPECT_EQ(move.kind, kind);
  EXPECT_NEAR(move.amount, amount, 1e-12);
}

TEST(MovesTest, CollinearStepsMergeIntoOneDrive) {
  const std::vector<Move> moves =
      MovesAlong(core::Pose2(0.0, 0.0, 0.0), {{0.1, 0.0}, {0.2, 0.0}, {0.3, 0.0}, {0.4, 0.0}});
  ASSERT_EQ(moves.size(), 1U);  // already facing the way: no turn
  ExpectMove(moves[0], Move::Kind::kStraight, 0.4);
}

TEST(MovesTest, TurnsToFaceEachLeg) {
  // Diagonal steps, then straight up, from a robot facing west.
  const std::vector<Move> moves = MovesAlong(
      core::Pose2(0.0, 0.0, kPi), {{0.1, 0.1}, {0.2, 0.2}, {0.2, 0.3}, {0.2, 0.4}, {0.2, 0.5}});
  ASSERT_EQ(moves.size(), 4U);
  ExpectMove(moves[0], Move::Kind::kTurn, -0.75 * kPi);  // west to north-east: the short way
  ExpectMove(moves[1], Move::Kind::kStraight, 0.2 * std::sqrt(2.0));
  ExpectMove(moves[2], Move::Kind::kTurn, 0.25 * kPi);
  ExpectMove(moves[3], Move::Kind::kStraight, 0.3);
}

TEST(MovesTest, TurningBackIsPlusPi) {
  const std::vector<Move> moves = MovesAlong(core::Pose2(1.0, 1.0, 0.0), {{2.0, 1.0}, {1.5, 1.0}});
  ASSERT_EQ(moves.size(), 3U);
  ExpectMove(moves[0], Move::Kind::kStraight, 1.0);
  ExpectMove(moves[1], Move::Kind::kTurn, kPi);  // in (-π, π]
  ExpectMove(moves[2], Move::Kind::kStraight, 0.5);
}

TEST(MovesTest, TurnsAreNormalised) {
  // Heading 170°, leg to -170°: a turn of +20°, not -340°.
  const std::vector<Move> moves =
      MovesAlong(core::Pose2(0.0, 0.0, core::DegToRad(170.0)),
                 {{std::cos(core::DegToRad(-170.0)), std::sin(core::DegToRad(-170.0))}});
  ASSERT_EQ(moves.size(), 2U);
  ExpectMove(moves[0], Move::Kind::kTurn, core::DegToRad(20.0));
  ExpectMove(moves[1], Move::Kind::kStraight, 1.0);
}

TEST(MovesTest, OffCentreStartIsItsOwnLeg) {
  // The robot is off its cell's centre line: the first leg is not collinear
  // with the next, so they are not merged.
  const std::vector<Move> moves = MovesAlong(core::Pose2(0.0, 0.01, 0.0), {{0.1, 0.0}, {0.2, 0.0}});
  ASSERT_EQ(moves.size(), 4U);
  EXPECT_EQ(moves[0].kind, Move::Kind::kTurn);
  EXPECT_EQ(moves[2].kind, Move::Kind::kTurn);
  EXPECT_NEAR(moves[0].amount + moves[2].amount, 0.0, 1e-12);
}

TEST(MovesTest, RepeatedAndEmptyWaypointsMakeNoMoves) {
  EXPECT_TRUE(MovesAlong(core::Pose2(0.3, 0.4, 1.0), {}).empty());
  EXPECT_TRUE(MovesAlong(core::Pose2(0.3, 0.4, 1.0), {{0.3, 0.4}, {0.3, 0.4}}).empty());
  const std::vector<Move> moves =
      MovesAlong(core::Pose2(0.0, 0.0, 0.0), {{0.1, 0.0}, {0.1, 0.0}, {0.2, 0.0}});
  ASSERT_EQ(moves.size(), 1U);
  ExpectMove(moves[0], Move::Kind::kStraight, 0.2);
}

TEST(MovesTest, MergeCollinearKeepsTurnsAndTheLastWaypoint) {
  const std::vector<Eigen::Vector2d> merged =
      MergeCollinear({0.0, 0.0}, {{0.1, 0.0}, {0.2, 0.0}, {0.2, 0.1}, {0.2, 0.2}});
  ASSERT_EQ(merged.size(), 2U);
  EXPECT_EQ(merged[0], Eigen::Vector2d(0.2, 0.0));
  EXPECT_EQ(merged[1], Eigen::Vector2d(0.2, 0.2));
  // A bend of 0.5° is a turn, not a straight run.
  const double bend = core::DegToRad(0.5);
  EXPECT_EQ(
      MergeCollinear({0.0, 0.0}, {{0.1, 0.0}, {0.1 + 0.1 * std::cos(bend), 0.1 * std::sin(bend)}})
          .size(),
      2U);
}

TEST(MovesTest, FollowingTheMovesEndsAtTheLastWaypoint) {
  const core::Pose2 start(0.05, -0.02, 2.0);
  const std::vector<Eigen::Vector2d> waypoints = {{0.1, 0.1},  {0.2, 0.2},  {0.2, 0.3},
                                                  {-0.1, 0.3}, {-0.1, 0.0}, {0.3, 0.4}};
  core::Pose2 pose = start;
  for (const Move& move : MovesAlong(start, waypoints)) {
    if (move.kind == Move::Kind::kTurn) {
      EXPECT_GT(move.amount, -kPi);
      EXPECT_LE(move.amount, kPi);
      pose = pose * core::Pose2(0.0, 0.0, move.amount);
    } else {
      EXPECT_GT(move.amount, 0.0);
      pose = pose * core::Pose2(move.amount, 0.0, 0.0);
    }
  }
  EXPECT_NEAR(pose.x(), 0.3, 1e-12);
  EXPECT_NEAR(pose.y(), 0.4, 1e-12);
}

}  // namespace
}  // namespace pirouette::explore
