#include "pirouette/robot/ros2/ros2_sample.h"

#include <cmath>

namespace pirouette::robot::ros2 {

void SetHeader(std_msgs_msg_dds__Header_& header, const builtin_interfaces_msg_dds__Time_& stamp,
               std::string_view frame) {
  header.stamp = stamp;
  SetString(header.frame_id, frame);
}

void SetString(char*& field, std::string_view text) {
  dds_string_free(field);
  field = static_cast<char*>(dds_alloc(text.size() + 1));
  std::memcpy(field, text.data(), text.size());
  field[text.size()] = '\0';
}

builtin_interfaces_msg_dds__Time_ RosTime(std::chrono::system_clock::time_point when) {
  const auto since_epoch =
      std::chrono::duration_cast<std::chrono::nanoseconds>(when.time_since_epoch());
  constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;
  builtin_interfaces_msg_dds__Time_ time{};
  time.sec = static_cast<std::int32_t>(since_epoch.count() / kNanosecondsPerSecond);
  time.nanosec = static_cast<std::uint32_t>(since_epoch.count() % kNanosecondsPerSecond);
  return time;
}

builtin_interfaces_msg_dds__Time_ RosTimeOfSeconds(double seconds) {
  return RosTime(std::chrono::system_clock::time_point(
      std::chrono::duration_cast<std::chrono::system_clock::duration>(
          std::chrono::duration<double>(seconds))));
}

double Seconds(const builtin_interfaces_msg_dds__Time_& time) {
  return static_cast<double>(time.sec) + 1e-9 * static_cast<double>(time.nanosec);
}

namespace {

// The quaternion of a rotation by `yaw` about z.
void SetYaw(geometry_msgs_msg_dds__Quaternion_& q, double yaw) {
  q.x = 0.0;
  q.y = 0.0;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
}

}  // namespace

void SetPose(geometry_msgs_msg_dds__Pose_& pose, const core::Pose2& pose2) {
  pose.position.x = pose2.translation().x();
  pose.position.y = pose2.translation().y();
  pose.position.z = 0.0;
  SetYaw(pose.orientation, pose2.heading());
}

core::Pose2 PoseOf(const geometry_msgs_msg_dds__Pose_& pose) {
  const auto& q = pose.orientation;
  // The yaw (ZYX Euler angles) in the form that holds for any norm: both
  // arguments scale with it, and atan2 only sees their ratio.
  const double yaw =
      std::atan2(2.0 * (q.w * q.z + q.x * q.y), q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z);
  return {pose.position.x, pose.position.y, std::isfinite(yaw) ? yaw : 0.0};
}

void SetTransform(geometry_msgs_msg_dds__Transform_& transform, const core::Pose2& pose2) {
  transform.translation.x = pose2.translation().x();
  transform.translation.y = pose2.translation().y();
  transform.translation.z = 0.0;
  SetYaw(transform.rotation, pose2.heading());
}

}  // namespace pirouette::robot::ros2
