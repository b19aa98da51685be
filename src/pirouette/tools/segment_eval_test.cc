#include "pirouette/tools/segment_eval.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

namespace pirouette::tools {
namespace {

TEST(SegmentationEvalJsonTest, GivesTheBoundaryErrorsOnlyWhereMeasured) {
  eval::SegmentationEvalRequest request;
  request.method = vision::SegmentationMethod::kPaper;
  request.first = 3;
  request.last = 4;
  eval::SegmentationEvalResult result;
  result.images = {{3, 0.912345, 0.95, 0.9}, {4, 0.5, 0.25, 1.0}};
  result.mean_iou = 0.7061725;
  const std::string photos = SegmentationEvalJson(request, result);
  EXPECT_EQ(photos.back(), '\n');
  const nlohmann::json json = nlohmann::json::parse(photos);
  EXPECT_EQ(json.at("method"), "paper");
  EXPECT_EQ(json.at("first"), 3);
  EXPECT_EQ(json.at("last"), 4);
  EXPECT_EQ(json.at("mean_iou"), 0.7062);
  EXPECT_FALSE(json.contains("boundary_error_median_px"));
  EXPECT_FALSE(json.contains("boundary_bias_median_px"));
  ASSERT_EQ(json.at("images").size(), 2u);
  EXPECT_EQ(json.at("images")[0].at("index"), 3);
  EXPECT_EQ(json.at("images")[0].at("iou"), 0.9123);
  EXPECT_EQ(json.at("images")[1].at("precision"), 0.25);

  result.boundary_error_median_px = 2.04;
  result.boundary_error_p95_px = 11.96;
  result.boundary_bias_median_px = -1.0;
  const nlohmann::json simulated = nlohmann::json::parse(SegmentationEvalJson(request, result));
  EXPECT_EQ(simulated.at("boundary_error_median_px"), 2.0);
  EXPECT_EQ(simulated.at("boundary_error_p95_px"), 12.0);
  EXPECT_EQ(simulated.at("boundary_bias_median_px"), -1.0);
}

}  // namespace
}  // namespace pirouette::tools
