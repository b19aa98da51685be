#include "pirouette/run/ros2_camera.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <stdexcept>

#include "pirouette/robot/robot_error.h"

namespace pirouette::run {
namespace {

constexpr const char* kSupportedModels = "plumb_bob, rational_polynomial and equidistant";

// K's items that must be 0 or 1 in pirouette's camera model: skew, the
// second row's first item and the last row.
struct FixedItem {
  int index;
  double value;
};
constexpr FixedItem kFixedItems[] = {{1, 0.0}, {3, 0.0}, {6, 0.0}, {7, 0.0}, {8, 1.0}};

camera::Intrinsics IntrinsicsOf(const std::array<double, 9>& k) {
  for (const double v : k) {
    if (!std::isfinite(v)) {
      throw std::invalid_argument("camera_info.k: holds a number that is not finite");
    }
  }
  if (!(k[0] > 0.0) || !(k[4] > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "camera_info.k: fx and fy must be > 0, got {} and {} (an uncalibrated camera's driver "
        "sends zeros: calibrate it, or give the intrinsics in the camera file)",
        k[0], k[4]));
  }
  for (const FixedItem& item : kFixedItems) {
    const auto i = static_cast<std::size_t>(item.index);
    if (k[i] != item.value) {
      throw std::invalid_argument(
          fmt::format("camera_info.k: item {} of 9 is {}, must be {} (the matrix is [fx 0 cx; "
                      "0 fy cy; 0 0 1])",
                      item.index + 1, k[i], item.value));
    }
  }
  return {k[0], k[4], k[2], k[5]};
}

}  // namespace

CameraFromInfo CameraFromCameraInfo(const robot::ros2::CameraInfo& info, const camera::Mount& mount,
                                    const camera::Vignetting& vignetting, const std::string& name) {
  if (info.width <= 0) {
    throw std::invalid_argument(fmt::format("camera_info.width: must be > 0, got {}", info.width));
  }
  if (info.height <= 0) {
    throw std::invalid_argument(
        fmt::format("camera_info.height: must be > 0, got {}", info.height));
  }
  const camera::Intrinsics intrinsics = IntrinsicsOf(info.k);
  std::string warning;
  camera::Distortion::Model model = camera::Distortion::Model::kPlumbBob;
  if (info.distortion_model.empty()) {
    warning = "camera_info has no distortion_model; read as plumb_bob, as ROS does";
  } else if (const auto named = camera::ModelNamed(info.distortion_model)) {
    model = *named;
  } else {
    throw std::invalid_argument(
        fmt::format("camera_info.distortion_model: unsupported distortion model '{}'; pirouette "
                    "reads {}",
                    info.distortion_model, kSupportedModels));
  }
  for (const double d : info.d) {
    if (!std::isfinite(d)) {
      throw std::invalid_argument("camera_info.d: holds a number that is not finite");
    }
  }
  const std::optional<camera::Distortion> distortion =
      camera::Distortion::FromCoefficients(model, info.d);
  if (!distortion) {
    camera::Distortion of_model;
    of_model.model = model;
    throw std::invalid_argument(fmt::format("camera_info.d: {} takes {} coefficients, got {}",
                                            camera::ModelName(model),
                                            of_model.Coefficients().size(), info.d.size()));
  }
  return {camera::CameraModel(name, info.width, info.height, intrinsics, *distortion, mount,
                              vignetting),
          warning};
}

camera::CameraModel CameraOfRos2Robot(robot::ros2::Ros2Robot& robot,
                                      const io::CameraMountFile& file, const std::string& path,
                                      std::chrono::milliseconds timeout,
                                      std::chrono::milliseconds peek,
                                      std::vector<std::string>& notes) {
  const std::string topic = robot.TopicName("camera_info");
  if (file.camera) {
    const std::optional<robot::ros2::CameraInfo> info = robot.WaitForCameraInfo(peek);
    if (info && (info->width != file.camera->width() || info->height != file.camera->height())) {
      notes.push_back(fmt::format(
          "warning: {} says {}×{} but the camera file {} says {}×{}; the camera file's "
          "intrinsics are used",
          topic, info->width, info->height, path, file.camera->width(), file.camera->height()));
    }
    return *file.camera;
  }
  const std::optional<robot::ros2::CameraInfo> info = robot.WaitForCameraInfo(timeout);
  const auto fail = [&](const std::string& what) -> robot::RobotError {
    robot.Halt();
    return robot::RobotError{fmt::format("the ROS 2 robot ({}): {}", robot.Describe(), what)};
  };
  if (!info) {
    throw fail(fmt::format(
        "no {} within {:g} s, and the camera file {} gives no intrinsics (camera_matrix): "
        "publish the camera's calibration on {}, or put it in the camera file",
        topic, std::chrono::duration<double>(timeout).count(), path, topic));
  }
  try {
    CameraFromInfo built = CameraFromCameraInfo(*info, file.mount, file.vignetting, file.name);
    if (file.width > 0 && (file.width != info->width || file.height != info->height)) {
      throw std::invalid_argument(fmt::format("the camera file {} says {}×{}, {} says {}×{}", path,
                                              file.width, file.height, topic, info->width,
                                              info->height));
    }
    if (!built.warning.empty()) {
      notes.push_back(fmt::format("{}: warning: {}", topic, built.warning));
    }
    notes.push_back(fmt::format("intrinsics from {} ({}×{}, {}); the mount from {}", topic,
                                info->width, info->height,
                                camera::ModelName(built.camera.distortion().model), path));
    robot.SetFrameSize(info->width, info->height);
    return built.camera;
  } catch (const std::invalid_argument& e) {
    throw fail(fmt::format("{}: {}", topic, e.what()));
  }
}

}  // namespace pirouette::run
