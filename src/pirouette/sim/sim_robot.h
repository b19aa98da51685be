#pragma once

#include <cstdint>
#include <functional>
#include <random>

#include "pirouette/robot/robot.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// The simulated robot: the paper's piecewise-linear motion in a World, with
// the world's odometry noise, and frames from a view function (the renderer).
//
// Motion model: a turn by θ turns the body by θ·(1 + b_r + ε_r), a straight
// move by d drives it d·(1 + b_t + ε_t) along its heading (b: the biases of
// OdometryNoise), ε_r ~ N(0, σ_r), ε_t ~ N(0, σ_t)
// drawn per move from a generator seeded with `seed`; odometry reports the
// commanded motion (what the wheel encoders believe). A straight move that
// would make the robot's disc touch an obstacle, a wall or the floor's edge
// stops at contact, and says so; odometry then reports the part made.
// The odometry frame starts at the world's start pose.
class SimRobot : public robot::Robot {
 public:
  // Renders what the camera sees with the robot at world_T_robot.
  using View = std::function<core::ImageRgb8(const core::Pose2& world_T_robot)>;

  SimRobot(const World& world, std::uint64_t seed, View view);
  // The same with another motion error than the world file's.
  SimRobot(const World& world, std::uint64_t seed, View view, const core::OdometryNoise& noise);

  core::MoveOutcome Execute(const core::Move& move) override;
  robot::Frame Capture() override;
  core::Pose2 Odometry() const override { return odom_T_robot_; }

  // The simulator's truth, never seen by the mapping code.
  const core::Pose2& TruePose() const { return world_T_robot_; }

 private:
  const World& world_;
  core::OdometryNoise noise_;
  View view_;
  std::mt19937_64 rng_;
  core::Pose2 world_T_robot_;
  core::Pose2 odom_T_robot_;
  double time_s_ = 0.0;
};

}  // namespace pirouette::sim
