#pragma once

#include <string>

#include "pirouette/camera/camera_model.h"

namespace YAML {
class Node;
}

namespace pirouette::camera {

// Reads a camera file (SPEC.md: ROS camera_info YAML plus `mount` and
// `vignetting`). Throws core::InputError naming the file, line and field for
// anything missing, of the wrong type or out of range.
CameraModel LoadCameraFile(const std::string& path);

// The same from a YAML node already read (a world file's inline camera);
// `file` names the file it came from, for messages, and `field_prefix` the
// node's place in it (e.g. "robot.camera"), so that fields read "robot.camera.mount.tilt".
CameraModel ParseCameraNode(const YAML::Node& node, const std::string& file,
                            const std::string& field_prefix);

// Writes `camera` as a camera file that LoadCameraFile reads back to the same
// values (atomically: a temporary file beside `path`, then a rename). Any
// CameraModel can be written. Throws std::runtime_error ("cannot write
// <path>: <step>: <reason>") when the file cannot be written; the temporary
// file is then removed and a file already at `path` is left as it was.
void SaveCameraFile(const CameraModel& camera, const std::string& path);

}  // namespace pirouette::camera
