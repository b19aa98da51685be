#pragma once

#include "pirouette/core/image.h"
#include "pirouette/core/pose2.h"

namespace pirouette::robot {

// One piecewise-linear motion, the only kind the paper's robot makes: a turn
// on the spot (radians, counter-clockwise positive) or a straight drive
// (metres, negative backwards).
struct Move {
  enum class Kind { kTurn, kStraight };

  Kind kind = Kind::kTurn;
  double amount = 0.0;

  static Move Turn(double radians) { return {Kind::kTurn, radians}; }
  static Move Straight(double metres) { return {Kind::kStraight, metres}; }
};

// What a move did, as the robot knows it.
struct MoveOutcome {
  Move requested;
  // The part of the move made, by odometry, in the move's unit; equal to
  // requested.amount unless the robot stopped early.
  double achieved = 0.0;
  // True when a straight move stopped because the robot touched something.
  bool stopped_at_contact = false;
  core::Pose2 odometry;  // odom_T_robot after the move
};

// One camera frame with the odometry at the moment it was taken.
struct Frame {
  core::ImageRgb8 image;
  core::Pose2 odometry;  // odom_T_robot
  double time_s = 0.0;   // since the robot started
};

// A robot that can turn on the spot, drive straight and take a picture: the
// simulator, a recorded run or a real robot over the network.
class Robot {
 public:
  virtual ~Robot() = default;

  virtual MoveOutcome Execute(const Move& move) = 0;
  virtual Frame Capture() = 0;
  virtual core::Pose2 Odometry() const = 0;
};

}  // namespace pirouette::robot
