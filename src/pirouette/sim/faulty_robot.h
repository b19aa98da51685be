#pragma once

#include <optional>

#include "pirouette/robot/robot.h"
#include "pirouette/sim/robot_fault.h"

namespace pirouette::sim {

// For testing: a Robot that passes every call to another and, from the
// fault's request on (RobotFault::from, counting TURN, MOVE and CAPTURE),
// misbehaves as the fault says: odometry shifted 1 m (teleport) or turned
// by π (flip) for good; frame stamps gone back 5 s (clock-back); the first
// faulty frame's bytes again and again (same-frame); each frame the one
// taken before the last move, with its stamp (late); frames in swapped pairs
// (out-of-order); moves made 0.3 of what is told (short-moves) or not at all
// (stalled). Faulty frames carry the odometry of their reply. half-frame is
// the server's (robot::RobotServerOptions) and changes nothing here.
class FaultyRobot : public robot::Robot {
 public:
  // `robot` must outlive this.
  FaultyRobot(robot::Robot& robot, const RobotFault& fault);

  core::MoveOutcome Execute(const core::Move& move) override;
  robot::Frame Capture() override;
  core::Pose2 Odometry() const override;

 private:
  // Counts a request; whether the fault applies to it.
  bool Faulty();
  // The odometry reported for the wrapped robot's `odometry`.
  core::Pose2 Reported(const core::Pose2& odometry) const;

  robot::Robot& robot_;
  RobotFault fault_;
  int requests_ = 0;
  bool started_ = false;              // the fault has begun
  std::optional<robot::Frame> held_;  // same-frame, late, out-of-order: a frame kept back
};

}  // namespace pirouette::sim
