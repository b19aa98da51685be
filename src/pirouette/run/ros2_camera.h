#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/robot/ros2/ros2_robot.h"

namespace pirouette::run {

// A camera built from a ROS 2 camera_info, with what the user should be told.
struct CameraFromInfo {
  camera::CameraModel camera;
  std::string warning;  // "" or one line for stderr (the caller prints it)
};

// The camera whose intrinsics and distortion are `info`'s (its size, K and
// its distortion model with D in ROS's order) and whose mount, vignetting
// and name are the camera file's. An empty distortion_model reads as
// plumb_bob, as ROS's camera_calibration_parsers read it, with a warning.
// Throws std::invalid_argument naming the field (camera_info.width,
// camera_info.height, camera_info.k, camera_info.distortion_model,
// camera_info.d) for what no camera has: a size ≤ 0, K not [fx 0 cx; 0 fy
// cy; 0 0 1] with fx, fy > 0 (an uncalibrated driver's K is all zero), a
// model pirouette does not read, or a count of coefficients the model does
// not take.
CameraFromInfo CameraFromCameraInfo(const robot::ros2::CameraInfo& info, const camera::Mount& mount,
                                    const camera::Vignetting& vignetting,
                                    const std::string& name = "");

// The camera of a run on a ROS 2 robot: the camera file's when it has
// intrinsics (then a camera_info of another size, if one comes within
// `peek`, only adds a warning); else camera_info's intrinsics, waited for up
// to `timeout`, with the file's mount, and the robot told the frame size.
// `notes` gets the lines to tell the user. Throws robot::RobotError when no
// camera_info comes, or it is not a camera's (naming the topic and the file).
camera::CameraModel CameraOfRos2Robot(robot::ros2::Ros2Robot& robot,
                                      const io::CameraMountFile& file, const std::string& path,
                                      std::chrono::milliseconds timeout,
                                      std::chrono::milliseconds peek,
                                      std::vector<std::string>& notes);

}  // namespace pirouette::run
