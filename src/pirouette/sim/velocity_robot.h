#pragma once

#include <cstdint>
#include <random>

#include "pirouette/core/odometry_noise.h"
#include "pirouette/core/pose2.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// How fast the simulated base follows a velocity command: a real base does
// not jump to a new speed, so a controller that drives it must ramp and
// brake (robot::ros2::MoveController).
struct VelocityLimits {
  double max_linear_mps = 0.5;      // |v| at most
  double max_angular_rps = 2.0;     // |ω| at most
  double linear_accel_mps2 = 1.0;   // |dv/dt| at most
  double angular_accel_rps2 = 4.0;  // |dω/dt| at most
};

// The simulated robot driven by velocity commands, as a ROS 2 base obeys
// `cmd_vel` (geometry_msgs/Twist: linear x forward, angular z
// counter-clockwise), stepped in simulated time by whoever owns the clock
// (the ROS 2 simulator server).
//
// Motion model: the executed velocity follows the command within
// VelocityLimits. The world's odometry noise is drawn once per motion (from
// rest to rest), as SimRobot draws it once per move: while it lasts, the body
// turns ω·dt·(1 + b_r + ε_r) and drives v·dt·(1 + b_t + ε_t) along its heading
// (ε ~ N(0, σ), drawn from a generator seeded with `seed`), and the odometry
// integrates the executed v·dt and ω·dt (what wheel encoders believe). A drive
// that would make the disc touch an obstacle, a wall or the floor's edge
// stops at contact (CastDisc) and the wheels stall: the odometry reports the
// part made, and the robot stays in contact while the command pushes on.
// The odometry frame starts at the world's start pose.
class VelocityRobot {
 public:
  VelocityRobot(const World& world, std::uint64_t seed, const core::OdometryNoise& noise,
                const VelocityLimits& limits = {});

  // Advances `dt` seconds (> 0) under the command (m/s, rad/s).
  void Step(double linear_mps, double angular_rps, double dt);

  const core::Pose2& odometry() const { return odom_T_robot_; }  // odom_T_robot
  const core::Pose2& true_pose() const { return world_T_robot_; }
  // The executed velocities, as the encoders measure them.
  double linear_mps() const { return linear_; }
  double angular_rps() const { return angular_; }
  double time_s() const { return time_s_; }
  // How long the robot has stood still (0 while it moves).
  double still_s() const { return still_s_; }
  // True while the last drive ended against something.
  bool in_contact() const { return in_contact_; }

 private:
  // Moves the body by `distance` along its heading (true metres), stopping
  // at contact; returns the true metres made.
  double Drive(double distance);

  const World& world_;
  core::OdometryNoise noise_;
  VelocityLimits limits_;
  std::mt19937_64 rng_;
  core::Pose2 world_T_robot_;
  core::Pose2 odom_T_robot_;
  double linear_ = 0.0;
  double angular_ = 0.0;
  double translation_error_ = 0.0;  // b_t + ε_t of the current motion
  double rotation_error_ = 0.0;     // b_r + ε_r of the current motion
  double time_s_ = 0.0;
  double still_s_ = 0.0;
  bool in_contact_ = false;
};

}  // namespace pirouette::sim
