#include "pirouette/tools/ipm_report.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "pirouette/core/input_error.h"

namespace pirouette::tools {
namespace {

double JsonNumber(const std::string& json, const std::string& field) {
  std::smatch match;
  const std::regex pattern("\"" + field + "\": ([0-9.eE+-]+)");
  if (!std::regex_search(json, match, pattern)) return -1.0;
  return std::stod(match[1]);
}

TEST(IpmReportTest, PaperCameraMaxRangeIsAboutFortyCentimetres) {
  IpmReportRequest request;
  request.camera_path = std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml";
  request.json = true;
  const std::string json = IpmReport(request);
  const double max_range = JsonNumber(json, "max_range_m");
  EXPECT_GE(max_range, 0.35) << json;
  EXPECT_LE(max_range, 0.45) << json;
  // The table's row at 0.35 m shows under half a centimetre.
  std::smatch match;
  ASSERT_TRUE(std::regex_search(json, match,
                                std::regex("\"range_m\": 0.350, \"row\": [0-9.]+, \"nearer_m\": "
                                           "([0-9.]+), \"farther_m\": ([0-9.]+)")))
      << json;
  EXPECT_LT(std::stod(match[2]), 0.005);
  // Coarser cells reach farther.
  request.cell_m = 0.02;
  EXPECT_GT(JsonNumber(IpmReport(request), "max_range_m"), max_range);
}

TEST(IpmReportTest, TextReportEndsWithTheMaxRange) {
  IpmReportRequest request;
  request.camera_path = std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml";
  const std::string text = IpmReport(request);
  EXPECT_NE(text.find("max range: 0.4"), std::string::npos) << text;
  EXPECT_NE(text.find("0.350"), std::string::npos) << text;
}

TEST(IpmReportTest, BadInputIsRefused) {
  IpmReportRequest request;
  request.camera_path = std::string(PIROUETTE_WORLDS_DIR) + "/no_such_camera.yaml";
  EXPECT_THROW(IpmReport(request), core::InputError);
  request.camera_path = std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml";
  request.cell_m = 0.0;
  EXPECT_THROW(IpmReport(request), core::InputError);
  request.cell_m = 0.01;
  request.step_m = -1.0;
  EXPECT_THROW(IpmReport(request), core::InputError);
}

}  // namespace
}  // namespace pirouette::tools
