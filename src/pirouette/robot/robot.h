#pragma once

#include "pirouette/core/image.h"
#include "pirouette/core/move.h"
#include "pirouette/core/pose2.h"

namespace pirouette::robot {

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

  virtual core::MoveOutcome Execute(const core::Move& move) = 0;
  virtual Frame Capture() = 0;
  virtual core::Pose2 Odometry() const = 0;
};

}  // namespace pirouette::robot
