#include "pirouette/tools/places.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/world_file.h"
#include "pirouette/run/explorer.h"

namespace pirouette::tools {
namespace {

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

TEST(PlacesTest, TheHeadingInvariantSignaturesFindMostPlaces) {
  PlacesRequest request;
  request.world_path = World("soccer_field");
  request.queries = 10;
  request.seed = 3;
  request.spacing_m = 0.25;
  request.quiet = true;
  const PlacesResult result = MeasurePlaces(request);
  EXPECT_GT(result.table_places, 10);
  ASSERT_EQ(result.scores.size(), 4u);
  int best = 0;
  for (const SignatureScore& s : result.scores) {
    EXPECT_LE(s.heading_hits, s.place_hits);
    if (localize::SignatureGivesHeading(s.kind)) best = std::max(best, s.heading_hits);
  }
  EXPECT_GE(best, 8) << "of 10";
  const nlohmann::json json = PlacesJson(request, result);
  EXPECT_EQ(json["format"], "pirouette-places-report/1");
  EXPECT_TRUE(json["signatures"].contains("colour"));
}

TEST(PlacesTest, BadRequestsAreInputErrors) {
  PlacesRequest request;
  request.world_path = World("soccer_field");
  request.queries = 0;
  EXPECT_THROW(MeasurePlaces(request), core::InputError);
  request.queries = 1;
  request.spacing_m = -1.0;
  EXPECT_THROW(MeasurePlaces(request), core::InputError);
}

}  // namespace
}  // namespace pirouette::tools
