// Fuzzes the CDR decoding of every ROS 2 message pirouette reads, and what
// turns each into pirouette's values: the input's first byte picks the type
// (nav_msgs/Odometry, sensor_msgs/Image, sensor_msgs/CameraInfo,
// geometry_msgs/Twist: what ros2_robot.cc and the ROS 2 simulator take),
// the rest is the sample's bytes with their encapsulation header. A sample
// DeserializeCdr accepts goes on to PoseOf and Seconds, ImageOf (at any size
// and at the camera's), or CameraFromCameraInfo; std::invalid_argument is
// their documented answer to a message that is no camera's or image's.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <utility>

#include "pirouette/robot/ros2/ros2_cdr.h"
#include "pirouette/robot/ros2/ros2_image.h"
#include "pirouette/robot/ros2/ros2_robot.h"
#include "pirouette/robot/ros2/ros2_sample.h"
#include "pirouette/run/ros2_camera.h"

namespace pirouette::robot::ros2 {
namespace {

// Decodes `bytes` as a T; checks that what decoded encodes to bytes that
// decode again.
template <class T>
bool Decode(std::span<const std::uint8_t> bytes, Sample<T>& message) {
  if (!DeserializeCdr(bytes, *MessageType<T>::Descriptor(), &*message)) return false;
  Sample<T> again;
  if (!DeserializeCdr(SerializeCdr(*message), *MessageType<T>::Descriptor(), &*again)) {
    std::abort();
  }
  return true;
}

void FuzzOdometry(std::span<const std::uint8_t> bytes) {
  Sample<nav_msgs_msg_dds__Odometry_> message;
  if (!Decode(bytes, message)) return;
  (void)Seconds(message->header.stamp);
  (void)PoseOf(message->pose.pose);
}

void FuzzImage(std::span<const std::uint8_t> bytes) {
  Sample<sensor_msgs_msg_dds__Image_> message;
  if (!Decode(bytes, message)) return;
  (void)Seconds(message->header.stamp);
  for (const auto& [width, height] : {std::pair{0, 0}, std::pair{4, 3}}) {
    try {
      (void)ImageOf(*message, width, height);
    } catch (const std::invalid_argument&) {
    }
  }
}

void FuzzCameraInfo(std::span<const std::uint8_t> bytes) {
  Sample<sensor_msgs_msg_dds__CameraInfo_> message;
  if (!Decode(bytes, message)) return;
  // As Ros2Robot takes a camera_info.
  CameraInfo info;
  info.width = static_cast<int>(message->width);
  info.height = static_cast<int>(message->height);
  info.distortion_model = message->distortion_model ? message->distortion_model : "";
  std::copy(std::begin(message->k), std::end(message->k), info.k.begin());
  info.d.assign(message->d._buffer, message->d._buffer + message->d._length);
  try {
    (void)run::CameraFromCameraInfo(info, camera::Mount{0.1, 0.5, 0.0}, camera::Vignetting{});
  } catch (const std::invalid_argument&) {
  }
}

void FuzzTwist(std::span<const std::uint8_t> bytes) {
  Sample<geometry_msgs_msg_dds__Twist_> message;
  (void)Decode(bytes, message);
}

}  // namespace
}  // namespace pirouette::robot::ros2

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::span<const std::uint8_t> bytes(data + 1, size - 1);
  switch (data[0] % 4) {
    case 0:
      pirouette::robot::ros2::FuzzOdometry(bytes);
      break;
    case 1:
      pirouette::robot::ros2::FuzzImage(bytes);
      break;
    case 2:
      pirouette::robot::ros2::FuzzCameraInfo(bytes);
      break;
    default:
      pirouette::robot::ros2::FuzzTwist(bytes);
      break;
  }
  return 0;
}
