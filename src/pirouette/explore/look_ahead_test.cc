#include "pirouette/explore/look_ahead.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace pirouette::explore {
namespace {

using core::ReadingKind;

// The paper's robot: radius 4 cm, readings trusted to 0.40 m, 1 cm cells.
LookAhead PaperLook() { return LookAhead(LookAheadOptions{0.04, 0.11, 0.40, 0.01}); }

// A profile of `n` readings across a 60° view, all of one kind at one range.
core::ObstacleProfile UniformProfile(ReadingKind kind, double range_m, int n = 61) {
  core::ObstacleProfile profile;
  profile.max_range_m = 0.40;
  for (int i = 0; i < n; ++i) {
    const double bearing = (30.0 - i) * std::numbers::pi / 180.0;
    profile.readings.push_back({bearing, range_m, kind});
  }
  return profile;
}

TEST(LookAheadTest, LongestCheckedMoveEndsTheSweptDiscWithinTheMaxRange) {
  EXPECT_DOUBLE_EQ(PaperLook().LongestCheckedMove(), 0.36);
  EXPECT_DOUBLE_EQ(LookAhead(LookAheadOptions{0.5, 0.1, 0.4, 0.01}).LongestCheckedMove(), 0.0);
}

TEST(LookAheadTest, FloorClearToTheMaxRangeLetsTheMoveGo) {
  const LookAhead::Finding finding =
      PaperLook().Blocking(UniformProfile(ReadingKind::kClear, 0.40), 0.30);
  EXPECT_EQ(finding.verdict, LookVerdict::kClear);
  EXPECT_TRUE(finding.hits_robot.empty());
}

TEST(LookAheadTest, AHitInTheSweptCorridorBlocksAndIsReturned) {
  core::ObstacleProfile profile = UniformProfile(ReadingKind::kClear, 0.40);
  profile.readings[30] = {0.0, 0.20, ReadingKind::kHit};  // straight ahead, 20 cm
  const LookAhead::Finding finding = PaperLook().Blocking(profile, 0.30);
  EXPECT_EQ(finding.verdict, LookVerdict::kBlocked);
  ASSERT_EQ(finding.hits_robot.size(), 1U);
  EXPECT_NEAR(finding.hits_robot[0].x(), 0.20, 1e-12);
  EXPECT_NEAR(finding.hits_robot[0].y(), 0.0, 1e-12);
}

TEST(LookAheadTest, TheFloorSeenOnlyPartWayVouchesForTheMoveOnlyThatFar) {
  // Clear to the max range: the whole move is vouched for.
  EXPECT_EQ(PaperLook().Blocking(UniformProfile(ReadingKind::kClear, 0.40), 0.30).seen_m,
            std::numeric_limits<double>::infinity());
  // Straight ahead the floor is seen free to 25 cm and unresolved past it:
  // the disc may go until its front is there.
  core::ObstacleProfile profile = UniformProfile(ReadingKind::kClear, 0.40);
  profile.readings[30] = {0.0, 0.25, ReadingKind::kClear};
  const LookAhead::Finding finding = PaperLook().Blocking(profile, 0.30);
  EXPECT_EQ(finding.verdict, LookVerdict::kClear);
  EXPECT_TRUE(finding.hits_robot.empty());
  EXPECT_NEAR(finding.seen_m, 0.25 - 0.04, 1e-12);
  // Beside the corridor (25° left at 20 cm: 8.5 cm off the path) it does not matter.
  core::ObstacleProfile beside = UniformProfile(ReadingKind::kClear, 0.40);
  beside.readings[5] = {25.0 * std::numbers::pi / 180.0, 0.20, ReadingKind::kClear};
  EXPECT_EQ(PaperLook().Blocking(beside, 0.30).seen_m, std::numeric_limits<double>::infinity());
}

TEST(LookAheadTest, HitsBeyondTheMoveOrBesideTheCorridorDoNotBlock) {
  core::ObstacleProfile profile = UniformProfile(ReadingKind::kClear, 0.40);
  // Ahead, but past the move's end by more than the corridor's half-width
  // (radius - cell = 3 cm).
  profile.readings[30] = {0.0, 0.35, ReadingKind::kHit};
  // 25° to the left at 20 cm: 8.5 cm beside the path.
  profile.readings[5] = {25.0 * std::numbers::pi / 180.0, 0.20, ReadingKind::kHit};
  EXPECT_EQ(PaperLook().Blocking(profile, 0.30).verdict, LookVerdict::kClear);
  // The same hit ahead blocks a longer move.
  EXPECT_EQ(PaperLook().Blocking(profile, 0.34).verdict, LookVerdict::kBlocked);
}

TEST(LookAheadTest, SomethingFillingTheViewAheadIsBlind) {
  core::ObstacleProfile profile = UniformProfile(ReadingKind::kClear, 0.40);
  for (int i = 25; i <= 35; ++i) profile.readings[i].kind = ReadingKind::kBlind;
  profile.readings[30].range_m = 0.11;
  EXPECT_EQ(PaperLook().Blocking(profile, 0.30).verdict, LookVerdict::kBlind);
  // A hit in the corridor says more than a blind bearing: blocked.
  profile.readings[28] = {2.0 * std::numbers::pi / 180.0, 0.15, ReadingKind::kHit};
  EXPECT_EQ(PaperLook().Blocking(profile, 0.30).verdict, LookVerdict::kBlocked);
}

}  // namespace
}  // namespace pirouette::explore
