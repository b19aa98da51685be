#include "pirouette/vision/intrinsics_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <optional>
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

// Views of the board seen through `camera`'s own model (CameraModel::Project),
// close and across the whole view so that a wide lens's edges are measured.
std::vector<ChessboardView> ViewsThrough(const camera::CameraModel& camera, double sigma) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, sigma);
  const std::vector<cv::Point3f> board = ChessboardObjectPoints(kPattern, kSquare);
  std::vector<ChessboardView> views;
  for (int i = 0; i < 16; ++i) {
    const cv::Vec3d rvec(0.6 * std::sin(1.3 * i + 0.4), 0.55 * std::cos(0.9 * i),
                         0.3 * std::sin(0.7 * i));
    const cv::Vec3d tvec(0.16 * std::sin(2.1 * i), 0.1 * std::cos(1.7 * i), 0.14 + 0.02 * (i % 4));
    cv::Matx33d rotation;
    cv::Rodrigues(rvec, rotation);
    std::vector<cv::Point2f> corners;
    for (const cv::Point3f& q : board) {
      const cv::Vec3d p = rotation * cv::Vec3d(q.x, q.y, q.z) + tvec;
      const std::optional<Eigen::Vector2d> pixel = camera.Project({p[0], p[1], p[2]});
      EXPECT_TRUE(pixel.has_value());
      corners.emplace_back(static_cast<float>(pixel->x() + noise(rng)),
                           static_cast<float>(pixel->y() + noise(rng)));
    }
    views.push_back({"view" + std::to_string(i), corners});
  }
  return views;
}

camera::CameraModel LensCamera(camera::Distortion::Model model, const std::vector<double>& k,
                               double f) {
  return {"lens",
          640,
          480,
          {f, f + 1.0, 318.0, 243.0},
          *camera::Distortion::FromCoefficients(model, k),
          {0.1, 0.5, 0.0},
          {}};
}

TEST(IntrinsicsCalibrationTest, RecoversAFisheyeThroughCvFisheye) {
  const std::vector<double> k = {0.04, -0.012, 0.003, -0.0005};
  const camera::CameraModel truth = LensCamera(camera::Distortion::Model::kEquidistant, k, 230.0);
  IntrinsicsCalibrationOptions options = Options();
  options.model = camera::Distortion::Model::kEquidistant;
  const IntrinsicsCalibration c =
      CalibrateIntrinsics(ViewsThrough(truth, 0.1), cv::Size(640, 480), options);
  EXPECT_EQ(c.distortion.model, camera::Distortion::Model::kEquidistant);
  EXPECT_NEAR(c.intrinsics.fx, 230.0, 1.0);
  EXPECT_NEAR(c.intrinsics.fy, 231.0, 1.0);
  EXPECT_NEAR(c.intrinsics.cx, 318.0, 1.0);
  EXPECT_NEAR(c.distortion.k1, 0.04, 0.01);
  EXPECT_LT(c.rms_px, 0.2);
  EXPECT_TRUE(c.dropped.empty());
}

TEST(IntrinsicsCalibrationTest, RecoversAWideAngleLensWithTheRationalModel) {
  const std::vector<double> k = {0.1, 0.01, 0.001, -0.0008, 0.0005, 0.45, 0.02, 0.0001};
  const camera::CameraModel truth =
      LensCamera(camera::Distortion::Model::kRationalPolynomial, k, 330.0);
  IntrinsicsCalibrationOptions options = Options();
  options.model = camera::Distortion::Model::kRationalPolynomial;
  const IntrinsicsCalibration c =
      CalibrateIntrinsics(ViewsThrough(truth, 0.1), cv::Size(640, 480), options);
  EXPECT_EQ(c.distortion.model, camera::Distortion::Model::kRationalPolynomial);
  EXPECT_NEAR(c.intrinsics.fx, 330.0, 3.0);
  EXPECT_NEAR(c.intrinsics.cx, 318.0, 1.5);
  EXPECT_LT(c.rms_px, 0.2);
  // The fitted lens maps the image as the true one does (its coefficients
  // trade off against each other, so they are not compared one by one).
  const camera::CameraModel fitted("fitted", 640, 480, c.intrinsics, c.distortion, {0.1, 0.5, 0.0},
                                   {});
  for (const Eigen::Vector2d& pixel :
       {Eigen::Vector2d(40, 40), Eigen::Vector2d(600, 300), Eigen::Vector2d(320, 460)}) {
    const std::optional<Eigen::Vector2d> back = truth.Project(fitted.Backproject(pixel));
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR((*back - pixel).norm(), 0.0, 1.5) << pixel.transpose();
  }
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
