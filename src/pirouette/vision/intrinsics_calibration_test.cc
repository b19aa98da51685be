#include "pirouette/vision/intrinsics_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace pirouette::vision {
namespace {

const cv::Size kPattern(9, 6);
constexpr double kSquare = 0.025;
const cv::Matx33d kCameraMatrix(500.0, 0.0, 318.0, 0.0, 502.0, 243.0, 0.0, 0.0, 1.0);
const cv::Matx<double, 1, 5> kDistortion(-0.25, 0.08, 0.001, -0.0005, 0.0);

// Views of the board at several tilts, turns and places, with corner noise of `sigma` pixels.
std::vector<ChessboardView> Views(double sigma) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, sigma);
  const std::vector<cv::Point3f> board = ChessboardObjectPoints(kPattern, kSquare);
  std::vector<ChessboardView> views;
  for (int i = 0; i < 12; ++i) {
    const double ax = 0.5 * std::sin(1.3 * i + 0.4);
    const double ay = 0.45 * std::cos(0.9 * i);
    const cv::Vec3d rvec(ax, ay, 0.3 * std::sin(0.7 * i));
    const cv::Vec3d tvec(0.06 * std::sin(2.1 * i), 0.04 * std::cos(1.7 * i), 0.32 + 0.02 * (i % 4));
    std::vector<cv::Point2f> corners;
    cv::projectPoints(board, rvec, tvec, kCameraMatrix, kDistortion, corners);
    for (cv::Point2f& p : corners) {
      p.x += static_cast<float>(noise(rng));
      p.y += static_cast<float>(noise(rng));
    }
    views.push_back({"view" + std::to_string(i), corners});
  }
  return views;
}

IntrinsicsCalibrationOptions Options() {
  IntrinsicsCalibrationOptions options;
  options.pattern = kPattern;
  options.square_m = kSquare;
  return options;
}

TEST(IntrinsicsCalibrationTest, RecoversTheCameraFromNoisyViews) {
  const IntrinsicsCalibration c = CalibrateIntrinsics(Views(0.1), cv::Size(640, 480), Options());
  EXPECT_NEAR(c.intrinsics.fx, 500.0, 1.5);
  EXPECT_NEAR(c.intrinsics.fy, 502.0, 1.5);
  EXPECT_NEAR(c.intrinsics.cx, 318.0, 1.5);
  EXPECT_NEAR(c.intrinsics.cy, 243.0, 1.5);
  EXPECT_NEAR(c.distortion.k1, -0.25, 0.01);
  EXPECT_NEAR(c.distortion.k2, 0.08, 0.02);
  EXPECT_DOUBLE_EQ(c.distortion.k3, 0.0);             // held at 0 with 2 radial coefficients
  EXPECT_NEAR(c.rms_px, 0.1 * std::sqrt(2.0), 0.02);  // 0.1 px along each axis
  EXPECT_EQ(c.used.size(), 12u);
  EXPECT_TRUE(c.dropped.empty());
}

TEST(IntrinsicsCalibrationTest, DropsAViewFarAboveTheRest) {
  std::vector<ChessboardView> views = Views(0.1);
  std::mt19937 rng(9);
  std::normal_distribution<double> noise(0.0, 3.0);
  for (cv::Point2f& p : views[4].corners) {
    p.x += static_cast<float>(noise(rng));
    p.y += static_cast<float>(noise(rng));
  }
  const IntrinsicsCalibration c = CalibrateIntrinsics(views, cv::Size(640, 480), Options());
  ASSERT_EQ(c.dropped.size(), 1u);
  EXPECT_EQ(c.dropped[0].name, "view4");
  EXPECT_GT(c.dropped[0].rms_px, 1.0);
  EXPECT_EQ(c.used.size(), 11u);
  EXPECT_NEAR(c.intrinsics.fx, 500.0, 1.5);
  EXPECT_LT(c.rms_px, 0.15);
}

TEST(IntrinsicsCalibrationTest, RefusesTooFewViewsOrWrongCorners) {
  std::vector<ChessboardView> views = Views(0.0);
  views.resize(2);
  EXPECT_THROW(CalibrateIntrinsics(views, cv::Size(640, 480), Options()), std::invalid_argument);
  views = Views(0.0);
  views[1].corners.pop_back();
  EXPECT_THROW(CalibrateIntrinsics(views, cv::Size(640, 480), Options()), std::invalid_argument);
}

TEST(IntrinsicsCalibrationTest, ObjectPointsAreCentredRowByRow) {
  const std::vector<cv::Point3f> points = ChessboardObjectPoints(cv::Size(3, 2), 0.1);
  ASSERT_EQ(points.size(), 6u);
  EXPECT_NEAR(points[0].x, -0.1, 1e-7);
  EXPECT_NEAR(points[0].y, -0.05, 1e-7);
  EXPECT_NEAR(points[1].x, 0.0, 1e-7);
  EXPECT_NEAR(points[5].x, 0.1, 1e-7);
  EXPECT_NEAR(points[5].y, 0.05, 1e-7);
}

}  // namespace
}  // namespace pirouette::vision
