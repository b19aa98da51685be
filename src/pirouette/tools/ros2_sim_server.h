#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "pirouette/core/image.h"
#include "pirouette/core/odometry_noise.h"
#include "pirouette/robot/ros2/dds_participant.h"
#include "pirouette/sim/robot_fault.h"
#include "pirouette/sim/velocity_robot.h"
#include "pirouette/sim/world.h"

namespace pirouette::tools {

struct Ros2SimServerOptions {
  int domain_id = 0;                // ROS_DOMAIN_ID
  robot::ros2::DdsNetwork network;  // loopback unless told
  std::string ros_namespace;        // the topics' namespace ("" none)
  // Simulated seconds a step lasts: odometry, tf and clock at 50 Hz.
  double step_s = 0.02;
  // While the robot is at rest, a frame every this many simulated seconds
  // (10 Hz); none while it moves, when a real camera's would be blurred.
  double frame_period_s = 0.1;
  // A base stops when cmd_vel has been silent this long (simulated seconds),
  // as real bases' drivers do when their controller dies.
  double command_timeout_s = 0.5;
  sim::VelocityLimits limits;
  // For testing (sim-serve --ros2 --fault): misbehaves so from `fault.from`
  // seconds of simulated time after the first cmd_vel on: odom and tf shifted 1 m (teleport) or
  // turned by π (flip); every stamp 5 s back (clock-back); the first faulty
  // frame's bytes again and again (same-frame); frames published kLateS after
  // they were taken (late) or in swapped pairs (out-of-order); cmd_vel obeyed
  // at kShortFraction of its speed (short-moves) or not at all (stalled).
  sim::RobotFault fault;
  // Set: Serve returns.
  const std::atomic<bool>* stop_requested = nullptr;
  // Told of each newly rendered frame with the true pose it was rendered at
  // (sim-serve --view), on the serving thread.
  std::function<void(const core::ImageRgb8&, const core::Pose2& world_T_robot)> on_render;
};

// The simulator as a ROS 2 robot (SPEC.md, "ROS 2 over DDS": sim-serve
// --ros2): obeys `cmd_vel` (geometry_msgs/Twist) with sim::VelocityRobot and
// the world's odometry noise, and publishes `odom` (nav_msgs/Odometry, frame
// odom, child base_link), `tf` (odom→base_link), `clock` (its simulated
// time: every stamp is on it, as a ROS 2 simulator's are), and while the
// robot is at rest `image_raw` (sensor_msgs/Image, rgb8, rendered at the true
// pose) with `camera_info`. Writers are reliable (they match best-effort and
// reliable readers alike); camera_info is transient-local.
//
// Time: each step advances as soon as a cmd_vel arrives, and after step_s of
// wall time otherwise. A client that answers every odometry reading with a
// command (a velocity controller) so drives the simulation as fast as the
// two can talk; one that sends nothing sees it run in real time.
class Ros2SimServer {
 public:
  // Throws robot::ros2::DdsError when DDS refuses the domain or the network.
  Ros2SimServer(const sim::World& world, std::uint64_t seed, const core::OdometryNoise& noise,
                const Ros2SimServerOptions& options);
  ~Ros2SimServer();
  Ros2SimServer(const Ros2SimServer&) = delete;
  Ros2SimServer& operator=(const Ros2SimServer&) = delete;

  // Steps until stop_requested is set.
  void Serve();
  // One step: waits up to `wait` for a command, then advances step_s and
  // publishes what the step made.
  void Step(std::chrono::milliseconds wait);

  const sim::VelocityRobot& robot() const;
  int frames_published() const;
  // Steps made (each published odom, tf and clock).
  long steps() const;
  // "rt/NS/odom"-style names, for the start-up message.
  std::string Describe() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pirouette::tools
