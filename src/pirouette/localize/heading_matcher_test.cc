#include "pirouette/localize/heading_matcher.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "pirouette/mapping/range_sensor_model.h"
#include "pirouette/testing/test_room.h"
#include "pirouette/testing/units.h"

namespace pirouette::localize {
namespace {

using testing::kPi;
using testing::kRoomCellM;

using testing::Frame;

using testing::kDeg;

// The map made from a pirouette of 12 frames at `at`.
mapping::OccupancyGrid PirouetteMap(const Eigen::Vector2d& at) {
  mapping::OccupancyGrid grid(
      core::GridGeometry(kRoomCellM, Eigen::Vector2d(-0.1043, -0.1057), 220, 170),
      mapping::OccupancyOptions{.hit_probability = 0.8, .miss_probability = 0.18});
  for (int k = 0; k < 12; ++k) {
    const core::Pose2 pose(at.x(), at.y(), k * kPi / 6.0);
    mapping::InsertProfile(grid, testing::Frame(pose), pose);
  }
  return grid;
}

TEST(MapProfileTest, ReadsWallsClearFloorAndTheUnknown) {
  const mapping::OccupancyGrid grid = PirouetteMap({0.6, 0.7});
  const MapProfile map(grid, {0.6, 0.7}, 1.2);
  // West: the wall x = 0, 0.6 m away.
  EXPECT_EQ(map.At(kPi).kind, MapRay::Kind::kHit);
  EXPECT_NEAR(map.At(kPi).range_m, 0.6, 0.01);
  // 30° north of east: floor beyond the camera's range (the wall 1.6 m away).
  EXPECT_EQ(map.At(30.0 * kDeg).kind, MapRay::Kind::kClear);
  // From outside the room nothing is known.
  const MapProfile outside(grid, {5.0, 5.0}, 1.2);
  EXPECT_EQ(outside.At(0.0).kind, MapRay::Kind::kUnknown);
}

TEST(HeadingMatcherTest, RecoversAKnownTurn) {
  const mapping::OccupancyGrid grid = PirouetteMap({0.6, 0.7});
  const MapProfile map(grid, {0.6, 0.7}, 1.2);
  for (const double heading : {-2.5, 0.4, 2.0}) {
    const core::ObstacleProfile profile = testing::Frame(core::Pose2(0.6, 0.7, heading));
    // The odometry says 2° more than the truth.
    const HeadingMatch match = MatchHeading(map, profile, heading + 2.0 * kDeg, 4.0 * kDeg);
    ASSERT_TRUE(match.accepted) << heading;
    EXPECT_NEAR(match.offset_rad, -2.0 * kDeg, 0.3 * kDeg) << heading;
  }
}

TEST(HeadingMatcherTest, AViewFindsItsTurnFromTheViewBefore) {
  const core::Pose2 first(0.6, 0.7, -2.0);
  const core::ObstacleProfile before = testing::Frame(first);
  const core::ObstacleProfile after = testing::Frame(core::Pose2(0.6, 0.7, -2.0 + 30.0 * kDeg));
  // The odometry says the turn was 31°.
  const HeadingMatch match =
      MatchToViews({{&before, first.heading()}}, after, first.heading() + 31.0 * kDeg, 2.5 * kDeg);
  ASSERT_TRUE(match.accepted);
  EXPECT_NEAR(match.offset_rad, -1.0 * kDeg, 0.4 * kDeg);
}

TEST(HeadingMatcherTest, TooLittleOverlapKeepsThePrediction) {
  const core::Pose2 first(0.6, 0.7, 0.0);
  const core::ObstacleProfile before = testing::Frame(first);
  // 90° on: the views do not overlap.
  const core::ObstacleProfile after = testing::Frame(core::Pose2(0.6, 0.7, kPi / 2.0));
  const HeadingMatch match = MatchToViews({{&before, 0.0}}, after, kPi / 2.0, 2.0 * kDeg);
  EXPECT_FALSE(match.accepted);
  EXPECT_DOUBLE_EQ(match.offset_rad, 0.0);
}

}  // namespace
}  // namespace pirouette::localize
