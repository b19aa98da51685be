#include "pirouette/vision/mount_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/testing/test_camera.h"
#include "pirouette/vision/intrinsics_calibration.h"

namespace pirouette::vision {
namespace {

const cv::Size kMountPattern(9, 6);
constexpr double kMountSquareM = 0.02;

// Where the camera sees the board's inner corners (ChessboardObjectPoints'
// order) when the board lies `surface` above the floor with its centre
// `distance` ahead of the robot's centre, turned by `yaw`, plus noise.
std::vector<cv::Point2f> SeenCorners(const camera::CameraModel& camera, double distance, double yaw,
                                     double surface, double sigma) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, sigma);
  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  std::vector<cv::Point2f> corners;
  for (const cv::Point3f& p : ChessboardObjectPoints(kMountPattern, kMountSquareM)) {
    const Eigen::Vector3d p_robot(distance + std::cos(yaw) * p.x - std::sin(yaw) * p.y,
                                  std::sin(yaw) * p.x + std::cos(yaw) * p.y, surface);
    const auto pixel = camera.Project(camera_T_robot * p_robot);
    EXPECT_TRUE(pixel.has_value());
    corners.emplace_back(static_cast<float>(pixel->x() + noise(rng)),
                         static_cast<float>(pixel->y() + noise(rng)));
  }
  return corners;
}

MountCalibrationOptions Options(double distance) {
  MountCalibrationOptions options;
  options.pattern = kMountPattern;
  options.square_m = kMountSquareM;
  options.board_distance_m = distance;
  return options;
}

TEST(MountCalibrationTest, RecoversHeightTiltAndForward) {
  const camera::CameraModel camera = testing::PaperCamera();  // 0.11 m, 30°, 0.03 m
  for (const double yaw : {0.0, 0.5, 1.5708}) {
    const MountCalibration m =
        CalibrateMount(SeenCorners(camera, 0.30, yaw, 0.0, 0.0), camera, Options(0.30));
    EXPECT_NEAR(m.mount.height_m, 0.11, 1e-5) << "yaw " << yaw;
    EXPECT_NEAR(core::RadToDeg(m.mount.tilt_rad), 30.0, 1e-3);
    EXPECT_NEAR(m.mount.forward_m, 0.03, 1e-5);
    EXPECT_NEAR(m.roll_rad, 0.0, 1e-5);
    EXPECT_NEAR(m.board_left_m, 0.0, 1e-5);
    EXPECT_LT(m.rms_px, 0.01);
  }
}

TEST(MountCalibrationTest, RecoversTheMountThroughAWideLensOrAFisheye) {
  using Model = camera::Distortion::Model;
  const camera::Mount mount{0.11, core::DegToRad(30.0), 0.03};
  const std::vector<camera::CameraModel> cameras = {
      camera::CameraModel("wide", 320, 240, {208.0, 208.0, 159.5, 119.5},
                          *camera::Distortion::FromCoefficients(
                              Model::kRationalPolynomial,
                              std::vector{0.1, 0.01, 0.001, -0.0008, 0.0005, 0.45, 0.02, 0.0001}),
                          mount, {}),
      camera::CameraModel("fisheye", 320, 240, {117.0, 117.0, 159.5, 119.5},
                          *camera::Distortion::FromCoefficients(
                              Model::kEquidistant, std::vector{0.04, -0.012, 0.003, -0.0005}),
                          mount, {}),
  };
  for (const camera::CameraModel& camera : cameras) {
    const MountCalibration m =
        CalibrateMount(SeenCorners(camera, 0.30, 0.3, 0.0, 0.0), camera, Options(0.30));
    EXPECT_NEAR(m.mount.height_m, 0.11, 1e-4) << camera.name();
    EXPECT_NEAR(core::RadToDeg(m.mount.tilt_rad), 30.0, 0.01) << camera.name();
    EXPECT_NEAR(m.mount.forward_m, 0.03, 1e-4) << camera.name();
    EXPECT_LT(m.rms_px, 0.01) << camera.name();
  }
}

TEST(MountCalibrationTest, NoisyCornersStayWithinAMillimetreAndATenthOfADegree) {
  const camera::CameraModel camera = testing::PaperCamera();
  const MountCalibration m =
      CalibrateMount(SeenCorners(camera, 0.30, 0.2, 0.0, 0.1), camera, Options(0.30));
  EXPECT_NEAR(m.mount.height_m, 0.11, 0.001);
  EXPECT_NEAR(core::RadToDeg(m.mount.tilt_rad), 30.0, 0.1);
  EXPECT_NEAR(m.mount.forward_m, 0.03, 0.003);
}

TEST(MountCalibrationTest, ThicknessOfTheBoardIsAddedToTheHeight) {
  const camera::CameraModel camera = testing::PaperCamera();
  MountCalibrationOptions options = Options(0.30);
  options.board_thickness_m = 0.005;
  const MountCalibration m =
      CalibrateMount(SeenCorners(camera, 0.30, 0.0, 0.005, 0.0), camera, options);
  EXPECT_NEAR(m.mount.height_m, 0.11, 1e-5);
}

TEST(MountCalibrationTest, RefusesBadOptionsAndCorners) {
  const camera::CameraModel camera = testing::PaperCamera();
  std::vector<cv::Point2f> corners = SeenCorners(camera, 0.30, 0.0, 0.0, 0.0);
  EXPECT_THROW(CalibrateMount(corners, camera, Options(0.0)), std::invalid_argument);
  corners.pop_back();
  EXPECT_THROW(CalibrateMount(corners, camera, Options(0.30)), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::vision
