#include "pirouette/tools/ipm_report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/core/input_error.h"

namespace pirouette::tools {
namespace {

TEST(IpmReportTest, PaperCameraMaxRangeIsAboutFortyCentimetres) {
  IpmReportRequest request;
  request.camera_path = std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml";
  request.json = true;
  const std::string text = IpmReport(request);
  const nlohmann::json json = nlohmann::json::parse(text);
  const double max_range = json.at("max_range_m").get<double>();
  EXPECT_GE(max_range, 0.35) << text;
  EXPECT_LE(max_range, 0.45) << text;
  // The table's row at 0.35 m shows under half a centimetre.
  const nlohmann::json* at_35cm = nullptr;
  for (const nlohmann::json& row : json.at("table")) {
    if (row.at("range_m").get<double>() == 0.35) at_35cm = &row;
  }
  ASSERT_NE(at_35cm, nullptr) << text;
  EXPECT_LT(at_35cm->at("farther_m").get<double>(), 0.005);
  // Coarser cells reach farther.
  request.cell_m = 0.02;
  EXPECT_GT(nlohmann::json::parse(IpmReport(request)).at("max_range_m").get<double>(), max_range);
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
