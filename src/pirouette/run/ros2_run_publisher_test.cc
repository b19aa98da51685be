#include "pirouette/run/ros2_run_publisher.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <thread>

#include "pirouette/robot/ros2/dds_reader.h"

namespace pirouette::run {
namespace {

namespace ros2 = robot::ros2;

constexpr int kDomain = 173;  // this test's own DDS domain

template <class F>
bool WaitUntil(F ready) {
  for (int i = 0; i < 500 && !ready(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return ready();
}

// One snapshot, read back as a ROS 2 subscriber sees it: the map's geometry
// and cells (bottom row first), tf map → odom, the path, the plan from the
// robot to its waypoints, and the status JSON.
TEST(Ros2RunPublisher, PublishesASnapshotAsRos2Messages) {
  Ros2RunPublisher publisher({kDomain, {}, "unit"});
  const ros2::DdsParticipant listener(kDomain, {});
  ros2::DdsReader<nav_msgs_msg_dds__OccupancyGrid_> map(listener, "unit/map", ros2::kMapQos);
  ros2::DdsReader<tf2_msgs_msg_dds__TFMessage_> tf(listener, "unit/tf", ros2::kTfQos);
  ros2::DdsReader<nav_msgs_msg_dds__Path_> plan(listener, "unit/pirouette/plan",
                                                ros2::kReliableQos);
  ros2::DdsReader<std_msgs_msg_dds__String_> status(listener, "unit/pirouette/status",
                                                    ros2::kLatchedQos);
  ASSERT_TRUE(WaitUntil([&] { return tf.MatchedWriters() == 1 && plan.MatchedWriters() == 1; }));

  mapping::OccupancyGrid grid(core::GridGeometry(0.05, Eigen::Vector2d(-1.0, -1.0), 40, 40));
  // One occupied cell low in the map and a free one above it, seen often from
  // two places (the map of record calls free only what two places saw free).
  for (int i = 0; i < 10; ++i) {
    grid.BeginFrame(Eigen::Vector2d(0.5 * (i % 2), 0.0));
    grid.Apply({10, 5}, mapping::CellUpdate::kHit);
    grid.Apply({10, 30}, mapping::CellUpdate::kMiss);
  }
  const std::vector<core::Pose2> path = {core::Pose2(0, 0, 0), core::Pose2(0.5, 0, 0)};
  const std::vector<Eigen::Vector2d> waypoints = {Eigen::Vector2d(0.5, 1.0)};
  const cv::Mat3b no_frame;
  const cv::Mat1b no_mask;
  ExplorationProgress progress;
  progress.pirouettes = 2;
  progress.known_area_m2 = 0.005;
  publisher.Publish(RunSnapshot{grid, path, path, waypoints, core::Pose2(0.5, 0, 0),
                                core::Pose2(0.1, -0.2, 0.3), no_frame, no_mask, 24, progress});

  ASSERT_TRUE(map.WaitForData(DDS_SECS(5)));
  const auto m = map.Take();
  ASSERT_TRUE(m.has_value());
  EXPECT_STREQ((*m)->header.frame_id, "map");
  EXPECT_FLOAT_EQ((*m)->info.resolution, 0.05F);
  // The seen part with its 5-cell margin: the columns 5..15, rows 0..35.
  const std::uint32_t w = (*m)->info.width;
  EXPECT_EQ(w, 11U);
  EXPECT_NEAR((*m)->info.origin.position.x, -1.0 + 5 * 0.05, 1e-9);
  EXPECT_NEAR((*m)->info.origin.position.y, -1.0, 1e-9);
  EXPECT_EQ((*m)->data._buffer[5 * w + 5], 100);  // cell (10, 5): row 5 from the bottom
  EXPECT_EQ((*m)->data._buffer[30 * w + 5], 0);
  EXPECT_EQ((*m)->data._buffer[20 * w + 5], -1);

  ASSERT_TRUE(tf.WaitForData(DDS_SECS(5)));
  const auto t = tf.Take();
  ASSERT_EQ((*t)->transforms._length, 1U);
  const auto& transform = (*t)->transforms._buffer[0];
  EXPECT_STREQ(transform.header.frame_id, "map");
  EXPECT_STREQ(transform.child_frame_id, "odom");
  EXPECT_NEAR(transform.transform.translation.y, -0.2, 1e-12);
  EXPECT_NEAR(2.0 * std::atan2(transform.transform.rotation.z, transform.transform.rotation.w), 0.3,
              1e-12);

  ASSERT_TRUE(plan.WaitForData(DDS_SECS(5)));
  const auto p = plan.Take();
  ASSERT_EQ((*p)->poses._length, 2U);  // from the robot, to the waypoint
  EXPECT_NEAR((*p)->poses._buffer[1].pose.position.y, 1.0, 1e-12);
  EXPECT_NEAR(ros2::PoseOf((*p)->poses._buffer[0].pose).heading(), std::numbers::pi / 2, 1e-12);

  ASSERT_TRUE(status.WaitForData(DDS_SECS(5)));
  const auto s = status.Take();
  const nlohmann::json json = nlohmann::json::parse((*s)->data);
  EXPECT_EQ(json["status"], "running");
  EXPECT_EQ(json["stops"], 2);
  EXPECT_DOUBLE_EQ(json["known_area_m2"].get<double>(), 0.005);
}

}  // namespace
}  // namespace pirouette::run
