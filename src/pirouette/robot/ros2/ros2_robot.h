#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pirouette/robot/move_controller.h"
#include "pirouette/robot/robot.h"
#include "pirouette/robot/ros2/dds_participant.h"

namespace pirouette::robot::ros2 {

// What a ROS 2 robot's camera_info said (sensor_msgs/CameraInfo).
struct CameraInfo {
  int width = 0;
  int height = 0;
  std::string distortion_model;
  std::array<double, 9> k{};  // the camera matrix, row-major
  std::vector<double> d;      // the distortion coefficients
};

struct Ros2RobotOptions {
  int domain_id = 0;
  DdsNetwork network;         // default: loopback only
  std::string ros_namespace;  // the robot's topics are NS/odom, NS/cmd_vel, …
  // The size frames must have (the camera file's); 0: any size but empty.
  int frame_width = 0;
  int frame_height = 0;
  MotionLimits limits;
  // The robot is at rest when odometry has moved less than these for
  // settle_s of the robot's clock; a frame is taken only then (the paper
  // captures while stationary: no blur, no vibration).
  double settle_s = 0.25;
  double rest_distance_m = 0.0005;
  double rest_angle_rad = 0.001;
  // A move whose progress stays under stall_progress for stall_s of the
  // robot's clock has stalled: a drive that got somewhere ended at contact;
  // a turn, or a drive that never started, means the robot does not obey.
  double stall_s = 1.0;
  double stall_progress_m = 0.001;
  double stall_progress_rad = 0.002;
  // Wall-clock limits: the first odometry and a subscriber of cmd_vel; the
  // longest silence of odometry; a new frame once at rest; coming to rest.
  std::chrono::milliseconds connect_timeout{10000};
  std::chrono::milliseconds odometry_timeout{2000};
  std::chrono::milliseconds frame_timeout{5000};
  std::chrono::milliseconds rest_timeout{10000};
  // Set: a move in progress stops early (Ctrl-C); the run then ends itself.
  const std::atomic<bool>* stop_requested = nullptr;
};

// A robot::Robot over DDS with ROS 2's topics (SPEC.md, "ROS 2 over DDS"):
// reads `odom` (nav_msgs/Odometry), `image_raw` (sensor_msgs/Image, rgb8 or
// bgr8) and `camera_info`, and drives with `cmd_vel` (geometry_msgs/Twist).
// Each move is closed on odometry (MoveController), with a command sent for
// every odometry reading (what a base's velocity controller expects), then
// the robot is left to come to rest before anything else happens.
//
// Every failure throws RobotError naming the topic: no odometry (at the
// start, or silent for odometry_timeout: "its publisher is gone" when
// discovery says so), a robot that does not move when told, one that does
// not come to rest, no new frame once at rest (a frozen camera repeats its
// stamp), a frame of another encoding or size. A zero Twist is sent before
// every throw, when a run ends (Halt) and when this object goes.
class Ros2Robot : public Robot {
 public:
  explicit Ros2Robot(const Ros2RobotOptions& options);
  ~Ros2Robot() override;
  Ros2Robot(const Ros2Robot&) = delete;
  Ros2Robot& operator=(const Ros2Robot&) = delete;

  core::MoveOutcome Execute(const core::Move& move) override;
  Frame Capture() override;
  core::Pose2 Odometry() const override;

  // Sends a zero Twist and waits (briefly) until the robot has it.
  void Halt();
  // The last camera_info received, if any.
  std::optional<CameraInfo> camera_info() const;
  // Waits (answering odometry with zero, as at rest) up to `timeout` for a
  // camera_info; nullopt when none came. Throws as Capture does when
  // odometry stops meanwhile.
  std::optional<CameraInfo> WaitForCameraInfo(std::chrono::milliseconds timeout);
  // From now on frames must be width × height (camera_info's size, when the
  // camera file gave none); 0: any size.
  void SetFrameSize(int width, int height);
  // The DDS name of one of the robot's topics ("rt/NS/camera_info").
  std::string TopicName(std::string_view relative) const;
  // "DDS domain N, namespace NS", for messages and run.json.
  std::string Describe() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pirouette::robot::ros2
