#include "pirouette/sim/faulty_robot.h"

#include <numbers>
#include <utility>

namespace pirouette::sim {

using Kind = RobotFault::Kind;

FaultyRobot::FaultyRobot(robot::Robot& robot, const RobotFault& fault)
    : robot_(robot), fault_(fault) {}

bool FaultyRobot::Faulty() {
  ++requests_;
  if (requests_ >= fault_.from) started_ = true;
  return started_;
}

core::Pose2 FaultyRobot::Reported(const core::Pose2& odometry) const {
  if (!started_) return odometry;
  if (fault_.kind == Kind::kTeleport) {
    return core::Pose2(RobotFault::kTeleportM, 0.0, 0.0) * odometry;
  }
  if (fault_.kind == Kind::kFlip) return odometry * core::Pose2(0.0, 0.0, std::numbers::pi);
  return odometry;
}

core::Pose2 FaultyRobot::Odometry() const { return Reported(robot_.Odometry()); }

core::MoveOutcome FaultyRobot::Execute(const core::Move& move) {
  const bool faulty = Faulty();
  core::MoveOutcome outcome;
  if (faulty && fault_.kind == Kind::kStalled) {
    outcome.requested = move;
    outcome.odometry = robot_.Odometry();
  } else if (faulty && fault_.kind == Kind::kShortMoves) {
    outcome = robot_.Execute({move.kind, RobotFault::kShortFraction * move.amount});
    outcome.requested = move;
  } else {
    outcome = robot_.Execute(move);
  }
  outcome.odometry = Reported(outcome.odometry);
  return outcome;
}

robot::Frame FaultyRobot::Capture() {
  const bool faulty = Faulty();
  robot::Frame frame = robot_.Capture();
  frame.odometry = Reported(frame.odometry);
  if (!faulty) {
    if (fault_.kind == Kind::kLate) held_ = frame;
    return frame;
  }
  switch (fault_.kind) {
    case Kind::kClockBack:
      frame.time_s -= RobotFault::kClockBackS;
      break;
    case Kind::kSameFrame:
      if (!held_) held_ = frame;
      frame.image = held_->image;
      break;
    case Kind::kLate:
      if (held_) {
        std::swap(frame.image, held_->image);
        std::swap(frame.time_s, held_->time_s);
      } else {
        held_ = frame;
      }
      break;
    case Kind::kOutOfOrder:
      if (held_) {
        frame.image = std::move(held_->image);
        frame.time_s = held_->time_s;
        held_.reset();
      } else {
        held_ = frame;  // the earlier of the pair, sent after the later one
        frame = robot_.Capture();
        frame.odometry = Reported(frame.odometry);
      }
      break;
    default:
      break;
  }
  return frame;
}

}  // namespace pirouette::sim
