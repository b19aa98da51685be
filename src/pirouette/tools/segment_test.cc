#include "pirouette/tools/segment.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

namespace pirouette::tools {
namespace {

TEST(ObstacleProfileJsonTest, OneReadingAColumnInDegreesAndMetres) {
  core::ObstacleProfile profile;
  profile.max_range_m = 0.412345;
  profile.readings = {{std::numbers::pi / 6, 0.2000004, core::ReadingKind::kHit},
                      {0.0, 0.412345, core::ReadingKind::kClear},
                      {-std::numbers::pi / 6, 0.05, core::ReadingKind::kBlind}};
  const std::string text = ObstacleProfileJson(profile);
  EXPECT_EQ(text.back(), '\n');
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json.at("max_range_m"), 0.4123);
  const nlohmann::json& readings = json.at("readings");
  ASSERT_EQ(readings.size(), 3u);
  EXPECT_EQ(readings[0].at("bearing_deg"), 30.0);
  EXPECT_EQ(readings[0].at("range_m"), 0.2);
  EXPECT_EQ(readings[0].at("kind"), "hit");
  EXPECT_EQ(readings[1].at("kind"), "clear");
  EXPECT_EQ(readings[2].at("bearing_deg"), -30.0);
  EXPECT_EQ(readings[2].at("kind"), "blind");
}

}  // namespace
}  // namespace pirouette::tools
