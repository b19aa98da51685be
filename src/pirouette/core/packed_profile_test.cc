#include "pirouette/core/packed_profile.h"

#include <gtest/gtest.h>

namespace pirouette::core {
namespace {

TEST(PackedProfileTest, UnpacksToTheProfileWithinFloatRounding) {
  ObstacleProfile profile;
  profile.max_range_m = 1.5;
  profile.readings = {{0.5236, 0.731234567, ReadingKind::kHit},
                      {0.0, 1.5, ReadingKind::kClear},
                      {-0.5236, 0.14, ReadingKind::kBlind}};
  const PackedProfile packed(profile);
  EXPECT_EQ(packed.size(), 3U);
  const ObstacleProfile back = packed.Unpack();
  EXPECT_EQ(back.max_range_m, 1.5);
  ASSERT_EQ(back.readings.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(back.readings[i].bearing_rad, profile.readings[i].bearing_rad, 1e-7);
    EXPECT_NEAR(back.readings[i].range_m, profile.readings[i].range_m, 1e-7);
    EXPECT_EQ(back.readings[i].kind, profile.readings[i].kind);
  }
  EXPECT_EQ(PackedProfile().Unpack().readings.size(), 0U);
}

TEST(PackedProfileTest, KeepsTheFeetApartFromTheColumns) {
  ObstacleProfile profile;
  profile.max_range_m = 1.0;
  profile.readings = {{0.1, 0.6, ReadingKind::kClear}, {0.0, 0.5, ReadingKind::kHit}};
  profile.feet = {{0.12, 0.45, ReadingKind::kHit}};
  const PackedProfile packed(profile);
  EXPECT_EQ(packed.size(), 3U);
  const ObstacleProfile back = packed.Unpack();
  ASSERT_EQ(back.readings.size(), 2U);
  ASSERT_EQ(back.feet.size(), 1U);
  EXPECT_NEAR(back.feet[0].bearing_rad, 0.12, 1e-7);
  EXPECT_NEAR(back.feet[0].range_m, 0.45, 1e-7);
  EXPECT_EQ(back.feet[0].kind, ReadingKind::kHit);
  EXPECT_EQ(back.readings[1].kind, ReadingKind::kHit);
}

}  // namespace
}  // namespace pirouette::core
