#include "pirouette/run/ros2_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

// The camera of a ROS 2 robot from its camera_info and the camera file's mount.
namespace pirouette::run::ros2_camera_test {
namespace {

using robot::ros2::CameraInfo;

CameraInfo PlumbBobInfo() {
  CameraInfo info;
  info.width = 320;
  info.height = 240;
  info.distortion_model = "plumb_bob";
  info.k = {277.0, 0.0, 159.5, 0.0, 276.0, 119.5, 0.0, 0.0, 1.0};
  info.d = {-0.2, 0.05, 0.001, -0.002, 0.01};
  return info;
}

constexpr camera::Mount kMount{0.11, 0.5, 0.03};

// The message of the std::invalid_argument that building from `info` throws.
std::string RefusalOf(const CameraInfo& info) {
  try {
    CameraFromCameraInfo(info, kMount, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "not refused";
  return "";
}

TEST(CameraFromCameraInfo, TakesIntrinsicsFromTheInfoAndTheMountFromTheFile) {
  const camera::Vignetting vignetting{{0.35, 0.3, 0.4}};
  const CameraFromInfo built = CameraFromCameraInfo(PlumbBobInfo(), kMount, vignetting, "yujin");
  EXPECT_TRUE(built.warning.empty());
  const camera::CameraModel& c = built.camera;
  EXPECT_EQ(c.name(), "yujin");
  EXPECT_EQ(c.width(), 320);
  EXPECT_EQ(c.height(), 240);
  EXPECT_EQ(c.intrinsics().fx, 277.0);
  EXPECT_EQ(c.intrinsics().fy, 276.0);
  EXPECT_EQ(c.intrinsics().cx, 159.5);
  EXPECT_EQ(c.intrinsics().cy, 119.5);
  EXPECT_EQ(c.distortion(), (camera::Distortion{-0.2, 0.05, 0.001, -0.002, 0.01}));
  EXPECT_EQ(c.mount().height_m, 0.11);
  EXPECT_EQ(c.mount().tilt_rad, 0.5);
  EXPECT_EQ(c.mount().forward_m, 0.03);
  EXPECT_EQ(c.vignetting().k, vignetting.k);
}

TEST(CameraFromCameraInfo, ReadsEveryModelInRosOrder) {
  CameraInfo info = PlumbBobInfo();
  info.distortion_model = "rational_polynomial";
  info.d = {0.1, 0.2, 0.001, 0.002, 0.3, 0.4, 0.5, 0.6};
  const camera::Distortion rational = CameraFromCameraInfo(info, kMount, {}).camera.distortion();
  EXPECT_EQ(rational.model, camera::Distortion::Model::kRationalPolynomial);
  EXPECT_EQ(rational.Coefficients(), info.d);
  info.distortion_model = "equidistant";
  info.d = {0.01, -0.02, 0.003, -0.004};
  const camera::Distortion fisheye = CameraFromCameraInfo(info, kMount, {}).camera.distortion();
  EXPECT_EQ(fisheye.model, camera::Distortion::Model::kEquidistant);
  EXPECT_EQ(fisheye.Coefficients(), info.d);
}

TEST(CameraFromCameraInfo, NoDistortionModelReadsAsPlumbBobWithAWarning) {
  CameraInfo info = PlumbBobInfo();
  info.distortion_model = "";
  const CameraFromInfo built = CameraFromCameraInfo(info, kMount, {});
  EXPECT_EQ(built.camera.distortion().model, camera::Distortion::Model::kPlumbBob);
  EXPECT_EQ(built.camera.distortion().k1, -0.2);
  EXPECT_NE(built.warning.find("plumb_bob"), std::string::npos) << built.warning;
}

TEST(CameraFromCameraInfo, RefusesAnUnknownModelOrTheWrongCoefficientCount) {
  CameraInfo info = PlumbBobInfo();
  info.distortion_model = "fov";
  const std::string model = RefusalOf(info);
  EXPECT_NE(model.find("camera_info.distortion_model"), std::string::npos) << model;
  EXPECT_NE(model.find("'fov'"), std::string::npos) << model;

  info = PlumbBobInfo();
  info.d = {0.1, 0.2, 0.3};
  const std::string count = RefusalOf(info);
  EXPECT_NE(count.find("camera_info.d"), std::string::npos) << count;
  EXPECT_NE(count.find("got 3"), std::string::npos) << count;
  info.distortion_model = "equidistant";
  info.d = {0.1, 0.2, 0.3, 0.4, 0.5};
  EXPECT_NE(RefusalOf(info).find("camera_info.d: equidistant takes 4"), std::string::npos);
  info.d = {0.1, 0.2, std::nan(""), 0.4};
  EXPECT_NE(RefusalOf(info).find("camera_info.d"), std::string::npos);
}

TEST(CameraFromCameraInfo, RefusesWhatIsNoCamerasMatrixOrSize) {
  CameraInfo info = PlumbBobInfo();
  info.k = {};  // an uncalibrated driver's
  EXPECT_NE(RefusalOf(info).find("camera_info.k: fx and fy must be > 0"), std::string::npos);
  for (const int index : {0, 4}) {
    info = PlumbBobInfo();
    info.k[static_cast<std::size_t>(index)] = -1.0;
    EXPECT_NE(RefusalOf(info).find("camera_info.k"), std::string::npos) << index;
  }
  for (const int index : {1, 3, 6, 7, 8}) {
    info = PlumbBobInfo();
    info.k[static_cast<std::size_t>(index)] = 0.5;
    EXPECT_NE(RefusalOf(info).find("camera_info.k: item"), std::string::npos) << index;
  }
  info = PlumbBobInfo();
  info.k[2] = std::numeric_limits<double>::infinity();
  EXPECT_NE(RefusalOf(info).find("camera_info.k"), std::string::npos);
  info = PlumbBobInfo();
  info.width = 0;
  EXPECT_NE(RefusalOf(info).find("camera_info.width"), std::string::npos);
  info = PlumbBobInfo();
  info.height = -3;
  EXPECT_NE(RefusalOf(info).find("camera_info.height"), std::string::npos);
}

}  // namespace
}  // namespace pirouette::run::ros2_camera_test
