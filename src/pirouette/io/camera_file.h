#pragma once

#include <optional>
#include <string>

#include "pirouette/camera/camera_model.h"

namespace YAML {
class Node;
}

namespace pirouette::io {

// Reads a camera file (SPEC.md: ROS camera_info YAML plus `mount` and
// `vignetting`). Throws core::InputError naming the file, line and field for
// anything missing, of the wrong type or out of range.
camera::CameraModel LoadCameraFile(const std::string& path);

// The same from a YAML node already read (a world file's inline camera);
// `file` names the file it came from, for messages, and `field_prefix` the
// node's place in it (e.g. "robot.camera"), so that fields read "robot.camera.mount.tilt".
camera::CameraModel ParseCameraNode(const YAML::Node& node, const std::string& file,
                                    const std::string& field_prefix);

// A camera file that may leave the intrinsics to the robot (a ROS 2 camera
// driver's camera_info): what `calibrate mount` measures is always the
// file's. `mount` is required; `camera_name`, `vignetting` and the image
// size (image_width and image_height together) are optional. With
// camera_matrix the file is a whole camera file (LoadCameraFile's rules);
// without it, distortion_model and distortion_coefficients are refused
// (coefficients without their camera matrix mean nothing).
struct CameraMountFile {
  std::string name;
  camera::Mount mount;
  camera::Vignetting vignetting;
  int width = 0;  // the image size the file gives; 0 when it gives none
  int height = 0;
  std::optional<camera::CameraModel> camera;  // when the file has intrinsics
};

// Reads such a file. Throws core::InputError naming the file, line and
// field, as LoadCameraFile does.
CameraMountFile LoadCameraMount(const std::string& path);

// The text of a camera file (ROS camera_info layout plus `mount` and
// `vignetting`) that LoadCameraFile reads back to the same values. Any
// CameraModel can be written. Writing it to disk (atomically) is the
// application's job: this layer does no I/O beyond reading its input.
std::string CameraFileText(const camera::CameraModel& camera);

}  // namespace pirouette::io
