// `pirouette segment` and `pirouette segment-eval` as a user meets them: the
// mask, the overlay, the profile JSON, and exit code 2 with a message naming
// the file for bad input (SPEC.md, "Commands").

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

using pirouette::testing::RunPirouette;
using Result = pirouette::testing::RunResult;

class SegmentCliTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return dir_ / name; }
  static std::string World(const std::string& name) {
    return std::string(PIROUETTE_WORLDS_DIR) + "/" + name;
  }

  pirouette::testing::TempDir dir_{"pirouette_segment_cli_test"};
};

TEST_F(SegmentCliTest, RenderedFrameGivesMaskOverlayAndProfile) {
  const std::string frame = Path("frame.png");
  ASSERT_EQ(RunPirouette("render --world " + World("soccer_field.yaml") +
                         " --pose 0.4,0.4,45 --out " + frame)
                .exit_code,
            0);
  for (const std::string method : {"paper", "default"}) {
    SCOPED_TRACE(method);
    std::string args = "segment --image " + frame;
    args += " --camera " + World("yujin.yaml");
    args += " --method " + method;
    args += " --mask " + Path("mask.png");
    args += " --out " + Path("overlay.png");
    const Result r = RunPirouette(args);
    ASSERT_EQ(r.exit_code, 0) << r.stderr_only;
    const nlohmann::json profile = nlohmann::json::parse(r.stdout_only);
    EXPECT_TRUE(profile.contains("max_range_m")) << r.stdout_only;
    ASSERT_EQ(profile.at("readings").size(), 320u);  // one reading per column
    for (const nlohmann::json& reading : profile.at("readings")) {
      EXPECT_TRUE(reading.contains("bearing_deg")) << reading;
    }
    const cv::Mat mask = cv::imread(Path("mask.png"), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(mask.type(), CV_8UC1);
    EXPECT_EQ(mask.cols, 320);
    EXPECT_EQ(mask.rows, 240);
    EXPECT_EQ(cv::countNonZero((mask != 0) & (mask != 255)), 0);
    EXPECT_GT(cv::countNonZero(mask), 320 * 240 / 10);
    EXPECT_EQ(cv::imread(Path("overlay.png")).size(), cv::Size(320, 240));
  }
}

TEST_F(SegmentCliTest, WithoutACameraPrintsNothing) {
  cv::Mat3b photo(120, 160, cv::Vec3b(90, 100, 110));
  cv::imwrite(Path("photo.png"), photo);
  const Result r =
      RunPirouette("segment --image " + Path("photo.png") + " --mask " + Path("mask.png"));
  EXPECT_EQ(r.exit_code, 0) << r.stderr_only;
  EXPECT_EQ(r.stdout_only, "");
  EXPECT_EQ(cv::imread(Path("mask.png"), cv::IMREAD_UNCHANGED).size(), cv::Size(160, 120));
}

TEST_F(SegmentCliTest, MissingImageIsBadInput) {
  const Result r = RunPirouette("segment --image " + Path("nothing.png"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("nothing.png"), std::string::npos) << r.stderr_only;
}

TEST_F(SegmentCliTest, EmptyFileIsBadInput) {
  dir_.Write("empty.png", "");
  const Result r = RunPirouette("segment --image " + Path("empty.png"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("empty.png"), std::string::npos) << r.stderr_only;
}

TEST_F(SegmentCliTest, ImageOfAnotherSizeThanTheCameraIsBadInput) {
  cv::imwrite(Path("small.png"), cv::Mat3b(120, 160, cv::Vec3b(90, 100, 110)));
  const Result r =
      RunPirouette("segment --image " + Path("small.png") + " --camera " + World("yujin.yaml"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("small.png"), std::string::npos) << r.stderr_only;
  EXPECT_NE(r.stderr_only.find("320"), std::string::npos) << r.stderr_only;
}

TEST_F(SegmentCliTest, UnknownMethodIsBadInput) {
  cv::imwrite(Path("photo.png"), cv::Mat3b(120, 160, cv::Vec3b(90, 100, 110)));
  const Result r = RunPirouette("segment --image " + Path("photo.png") + " --method magic");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("magic"), std::string::npos) << r.stderr_only;
}

TEST_F(SegmentCliTest, EvalOfAFolderWithoutPhotosIsBadInput) {
  const Result r = RunPirouette("segment-eval --images " + dir_.path().string() + " --last 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("source_0.bmp"), std::string::npos) << r.stderr_only;
}

}  // namespace
