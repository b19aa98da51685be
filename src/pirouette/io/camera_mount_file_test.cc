#include <gtest/gtest.h>

#include <string>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/testing/input_error.h"
#include "pirouette/testing/temp_dir.h"

// A camera file that leaves the intrinsics to a ROS 2 robot's camera_info.
namespace pirouette::io::camera_mount_file_test {
namespace {

using testing::ExpectInputError;
using testing::TempDir;

// What `calibrate mount` gives, with a name and vignetting; the tests below
// refer to its line numbers.
constexpr char kMountOnly[] =
    "camera_name: front\n"      // 1
    "mount:\n"                  // 2
    "  height: 0.11\n"          // 3
    "  tilt: 30\n"              // 4
    "  forward: 0.03\n"         // 5
    "vignetting:\n"             // 6
    "  k: [0.35, 0.3, 0.4]\n";  // 7

constexpr char kWholeCamera[] =
    "image_width: 320\n"
    "image_height: 240\n"
    "camera_matrix: {rows: 3, cols: 3, data: [277.13, 0, 159.5, 0, 276.5, 119.25, 0, 0, 1]}\n"
    "distortion_model: plumb_bob\n"
    "distortion_coefficients: {rows: 1, cols: 5, data: [-0.2, 0.05, 0, 0, 0]}\n"
    "mount: {height: 0.2, tilt: 20}\n";

TEST(CameraMountFileTest, AMountWithoutIntrinsicsLoads) {
  const TempDir dir;
  const CameraMountFile file = LoadCameraMount(dir.Write("mount.yaml", kMountOnly));
  EXPECT_FALSE(file.camera.has_value());
  EXPECT_EQ(file.name, "front");
  EXPECT_EQ(file.mount.height_m, 0.11);
  EXPECT_EQ(file.mount.tilt_rad, core::DegToRad(30.0));
  EXPECT_EQ(file.mount.forward_m, 0.03);
  EXPECT_EQ(file.vignetting.k, (std::array<double, 3>{0.35, 0.3, 0.4}));
  EXPECT_EQ(file.width, 0);
  EXPECT_EQ(file.height, 0);
}

TEST(CameraMountFileTest, AnImageSizeIsKeptWhenGiven) {
  const TempDir dir;
  const CameraMountFile file = LoadCameraMount(
      dir.Write("mount.yaml", std::string("image_width: 640\nimage_height: 480\n") + kMountOnly));
  EXPECT_EQ(file.width, 640);
  EXPECT_EQ(file.height, 480);
  const std::string half = dir.Write("half.yaml", std::string("image_width: 640\n") + kMountOnly);
  const core::InputError error = ExpectInputError([&] { LoadCameraMount(half); });
  EXPECT_EQ(error.field(), "image_height");
}

TEST(CameraMountFileTest, AWholeCameraFileGivesItsCamera) {
  const TempDir dir;
  const std::string path = dir.Write("camera.yaml", kWholeCamera);
  const CameraMountFile file = LoadCameraMount(path);
  ASSERT_TRUE(file.camera.has_value());
  EXPECT_EQ(file.camera->intrinsics().fx, 277.13);
  EXPECT_EQ(file.camera->width(), 320);
  EXPECT_EQ(file.width, 320);
  EXPECT_EQ(file.mount.height_m, 0.2);
  EXPECT_EQ(file.camera->mount().tilt_rad, LoadCameraFile(path).mount().tilt_rad);
}

TEST(CameraMountFileTest, CoefficientsWithoutTheirMatrixAreRefused) {
  const TempDir dir;
  const std::string path = dir.Write(
      "mount.yaml", std::string(kMountOnly) +
                        "distortion_coefficients: {rows: 1, cols: 5, data: [0, 0, 0, 0, 0]}\n");
  const core::InputError error = ExpectInputError([&] { LoadCameraMount(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), "distortion_coefficients");
  EXPECT_EQ(error.line(), 8);
  EXPECT_NE(std::string(error.what()).find("without camera_matrix"), std::string::npos);
  const std::string model =
      dir.Write("model.yaml", std::string(kMountOnly) + "distortion_model: plumb_bob\n");
  EXPECT_EQ(ExpectInputError([&] { LoadCameraMount(model); }).field(), "distortion_model");
}

TEST(CameraMountFileTest, TheMountIsRequiredAndCheckedAtItsLine) {
  const TempDir dir;
  const std::string none = dir.Write("none.yaml", "camera_name: front\n");
  EXPECT_EQ(ExpectInputError([&] { LoadCameraMount(none); }).field(), "mount");
  std::string text = kMountOnly;
  text.replace(text.find("tilt: 30"), 8, "tilt: 95");
  const std::string steep = dir.Write("steep.yaml", text);
  const core::InputError error = ExpectInputError([&] { LoadCameraMount(steep); });
  EXPECT_EQ(error.field(), "mount.tilt");
  EXPECT_EQ(error.line(), 4);
  const std::string unknown = dir.Write("unknown.yaml", std::string(kMountOnly) + "lens: 2\n");
  EXPECT_EQ(ExpectInputError([&] { LoadCameraMount(unknown); }).line(), 8);
}

}  // namespace
}  // namespace pirouette::io::camera_mount_file_test
