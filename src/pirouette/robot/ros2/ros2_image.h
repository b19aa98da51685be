#pragma once

#include "pirouette/core/image.h"
#include "pirouette/robot/ros2/ros2_message_type.h"

namespace pirouette::robot::ros2 {

// The RGB image of a sensor_msgs/Image in rgb8 or bgr8, rows `step` bytes
// apart. Throws std::invalid_argument saying what is wrong (another
// encoding, named; a size other than width × height where those are
// non-zero; a step or data too short for the size) and never reads past the
// message's data.
core::ImageRgb8 ImageOf(const sensor_msgs_msg_dds__Image_& message, int width = 0, int height = 0);

// Fills a sensor_msgs/Image with `image` as rgb8 (header left as it is).
void SetImage(sensor_msgs_msg_dds__Image_& message, const core::ImageRgb8& image);

}  // namespace pirouette::robot::ros2
