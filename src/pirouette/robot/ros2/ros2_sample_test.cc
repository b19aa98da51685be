#include "pirouette/robot/ros2/ros2_sample.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace pirouette::robot::ros2 {
namespace {

TEST(Ros2Sample, PosesGoThroughQuaternions) {
  for (const double yaw : {0.0, 0.3, -2.0, std::numbers::pi - 1e-9}) {
    geometry_msgs_msg_dds__Pose_ pose{};
    SetPose(pose, core::Pose2(1.5, -2.0, yaw));
    EXPECT_DOUBLE_EQ(pose.position.x, 1.5);
    EXPECT_NEAR(pose.orientation.z * pose.orientation.z + pose.orientation.w * pose.orientation.w,
                1.0, 1e-12);
    const core::Pose2 back = PoseOf(pose);
    EXPECT_NEAR(back.translation().y(), -2.0, 1e-12);
    EXPECT_NEAR(core::NormalizeAngle(back.heading() - yaw), 0.0, 1e-9) << yaw;
  }
}

TEST(Ros2Sample, AnUnnormalisedOrZeroQuaternionReadsSafely) {
  geometry_msgs_msg_dds__Pose_ pose{};
  pose.orientation.z = 2.0 * std::sin(0.25);
  pose.orientation.w = 2.0 * std::cos(0.25);
  EXPECT_NEAR(PoseOf(pose).heading(), 0.5, 1e-12);
  pose.orientation = {};
  EXPECT_EQ(PoseOf(pose).heading(), 0.0);
}

TEST(Ros2Sample, TimeSplitsIntoSecondsAndNanoseconds) {
  const auto when =
      std::chrono::system_clock::time_point(std::chrono::nanoseconds(1'700'000'000'250'000'000));
  const auto time = RosTime(when);
  EXPECT_EQ(time.sec, 1'700'000'000);
  EXPECT_EQ(time.nanosec, 250'000'000U);
  EXPECT_DOUBLE_EQ(Seconds(time), 1'700'000'000.25);
}

TEST(Ros2Sample, OwnsItsStringsAndSequences) {
  Sample<sensor_msgs_msg_dds__Image_> image;
  SetString(image->encoding, "rgb8");
  SetString(image->encoding, "bgr8");  // the first is freed
  const std::vector<std::uint8_t> pixels(12, 7);
  SetSequence(image->data, std::span<const std::uint8_t>(pixels));
  SetSequence(image->data, std::span<const std::uint8_t>(pixels.data(), 6));
  EXPECT_STREQ(image->encoding, "bgr8");
  EXPECT_EQ(image->data._length, 6U);
  Sample<sensor_msgs_msg_dds__Image_> moved = std::move(image);
  EXPECT_STREQ(moved->encoding, "bgr8");
  EXPECT_EQ(image->encoding, nullptr);  // NOLINT(bugprone-use-after-move): moved-from is empty
}

TEST(Ros2Sample, SequencesOfStructsAreFilledInPlace) {
  Sample<nav_msgs_msg_dds__Path_> path;
  ResizeSequence(path->poses, 3);
  for (std::uint32_t i = 0; i < path->poses._length; ++i) {
    SetString(path->poses._buffer[i].header.frame_id, "map");
    SetPose(path->poses._buffer[i].pose, core::Pose2(i, 0.0, 0.0));
  }
  EXPECT_EQ(path->poses._length, 3U);
  EXPECT_DOUBLE_EQ(path->poses._buffer[2].pose.position.x, 2.0);
}

}  // namespace
}  // namespace pirouette::robot::ros2
