#pragma once

#include "pirouette/core/move.h"
#include "pirouette/core/pose2.h"

namespace pirouette::robot {

// How a velocity-driven base is driven through one move. The defaults suit a
// small indoor robot (a TurtleBot 3 drives at most 0.22 m/s and turns at
// 2.8 rad/s); the paper's robot moves slowly and captures only at rest.
struct MotionLimits {
  double max_linear_mps = 0.2;     // cruising speed of a drive
  double max_angular_rps = 1.0;    // cruising rate of a turn (57°/s)
  double linear_accel_mps2 = 0.5;  // ramp up and brake
  double angular_accel_rps2 = 2.0;
  // Slowest command while the goal is not reached: below it some bases do
  // not move at all (static friction, dead bands of motor drivers).
  double min_linear_mps = 0.02;
  double min_angular_rps = 0.1;
  // The move is done when odometry is this close to its goal (or half the
  // move's size, if that is less): about what odometry resolves, and well
  // under the map's cell (1–2 cm).
  double distance_tolerance_m = 0.003;
  double angle_tolerance_rad = 0.004;  // 0.23°
};

// The velocity command of a base (geometry_msgs/Twist's linear.x and angular.z).
struct Velocity {
  double linear_mps = 0.0;
  double angular_rps = 0.0;
};

// Closes one move (a turn on the spot or a straight drive) on odometry: a
// trapezoidal speed profile, ramped up from rest with the acceleration, at
// most the cruising speed, and braking as √(2·a·remaining) so that it comes to
// rest at the goal; never slower than the minimum speed until the goal is
// within the tolerance. Progress is measured along the move: a turn's
// accumulated heading change (unwrapped, so turns past 180° work), a drive's
// displacement projected on the heading at its start. Pure: fed odometry
// readings with their time, it answers the command to send.
class MoveController {
 public:
  MoveController(const core::Move& move, const core::Pose2& start, double start_time_s,
                 const MotionLimits& limits = {});

  // Takes one odometry reading (odom_T_robot at `time_s`, the base's clock)
  // and returns the command to send now: zero once the goal is reached.
  Velocity Update(const core::Pose2& odometry, double time_s);

  // The part of the move made so far, in its unit and sign (radians or metres).
  double progress() const { return progress_; }
  // Whether progress is within the tolerance of the goal (or past it).
  bool reached() const;
  const core::Move& move() const { return move_; }

 private:
  core::Move move_;
  core::Pose2 start_;
  double start_time_s_;
  MotionLimits limits_;
  core::Pose2 last_;
  double progress_ = 0.0;
};

}  // namespace pirouette::robot
