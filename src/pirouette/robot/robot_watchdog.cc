#include "pirouette/robot/robot_watchdog.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "pirouette/core/angle.h"
#include "pirouette/robot/robot_error.h"

namespace pirouette::robot {
namespace {

bool IsTurn(const core::Move& move) { return move.kind == core::Move::Kind::kTurn; }

// "TURN 30.0°", "MOVE 0.250 m": a move for a reason.
std::string Describe(const core::Move& move) {
  return IsTurn(move) ? fmt::format("TURN {:.1f}°", core::RadToDeg(move.amount))
                      : fmt::format("MOVE {:.3f} m", move.amount);
}

std::string Amount(const core::Move& move, double amount) {
  return IsTurn(move) ? fmt::format("{:.1f}°", core::RadToDeg(amount))
                      : fmt::format("{:.3f} m", amount);
}

bool SameBytes(const core::ImageRgb8& a, const core::ImageRgb8& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::equal(a.data(), a.data() + a.size_bytes(), b.data());
}

}  // namespace

RobotWatchdog::RobotWatchdog(Robot& robot, std::string name, const RobotWatchdogOptions& options)
    : robot_(robot), name_(std::move(name)), options_(options), odometry_(robot.Odometry()) {}

void RobotWatchdog::Fail(const std::string& what) const {
  throw RobotError(fmt::format("{} {}", name_, what));
}

core::MoveOutcome RobotWatchdog::Execute(const core::Move& move) {
  const core::Pose2 before = odometry_;
  core::MoveOutcome outcome = robot_.Execute(move);
  CheckMove(move, outcome, before);
  CheckMotionMade(move, outcome);
  odometry_ = outcome.odometry;
  return outcome;
}

void RobotWatchdog::CheckMove(const core::Move& move, const core::MoveOutcome& outcome,
                              const core::Pose2& before) {
  const core::Pose2 delta = before.Inverse() * outcome.odometry;  // in the robot's frame before
  const double moved_m = delta.translation().norm();
  const double turned_rad = delta.heading();
  const double most_m =
      IsTurn(move) ? options_.max_jump_m : std::abs(move.amount) + options_.max_jump_m;
  if (moved_m > most_m) {
    Fail(
        fmt::format("reported odometry that jumped {:.2f} m over {} (at most {:.2f} m is "
                    "possible): its odometry cannot be trusted",
                    moved_m, Describe(move), most_m));
  }
  const double said_rad = IsTurn(move) ? outcome.achieved : 0.0;
  const double mismatch_rad = std::abs(core::NormalizeAngle(turned_rad - said_rad));
  if (mismatch_rad > options_.max_jump_rad) {
    Fail(
        fmt::format("reported a heading that jumped {:.0f}° over {} (it says it turned {:.1f}°, "
                    "its odometry {:.1f}°): its odometry cannot be trusted",
                    core::RadToDeg(mismatch_rad), Describe(move), core::RadToDeg(said_rad),
                    core::RadToDeg(turned_rad)));
  }
  const double overshoot = std::abs(outcome.achieved) - std::abs(move.amount);
  if (overshoot > (IsTurn(move) ? options_.max_jump_rad : options_.max_jump_m)) {
    Fail(fmt::format("says it made {} of {}: its odometry cannot be trusted",
                     Amount(move, outcome.achieved), Describe(move)));
  }
}

void RobotWatchdog::CheckMotionMade(const core::Move& move, const core::MoveOutcome& outcome) {
  const double made = std::abs(outcome.achieved);
  const bool idle = made < (IsTurn(move) ? options_.idle_rad : options_.idle_m);
  if (!idle) moved_since_frame_ = true;
  if (std::abs(move.amount) < (IsTurn(move) ? options_.min_judged_rad : options_.min_judged_m)) {
    return;
  }
  if (outcome.stopped_at_contact) {
    idle_moves_ = short_moves_ = 0;
    return;
  }
  idle_moves_ = idle ? idle_moves_ + 1 : 0;
  short_moves_ =
      !idle && made < options_.min_fraction * std::abs(move.amount) ? short_moves_ + 1 : 0;
  if (idle_moves_ >= options_.max_idle_moves) {
    Fail(fmt::format("did not move: {} moves in a row made nothing (the last, {}, made {})",
                     idle_moves_, Describe(move), Amount(move, outcome.achieved)));
  }
  if (short_moves_ >= options_.max_short_moves) {
    Fail(
        fmt::format("moves less than it is told: {} moves in a row made under {:.0f}% of what "
                    "was asked (the last, {}, made {}); check the units and scale of its "
                    "adapter",
                    short_moves_, 100.0 * options_.min_fraction, Describe(move),
                    Amount(move, outcome.achieved)));
  }
}

Frame RobotWatchdog::Capture() {
  Frame frame = robot_.Capture();
  CheckFrame(frame);
  moved_since_frame_ = false;
  last_frame_ = frame;
  return frame;
}

void RobotWatchdog::CheckFrame(const Frame& frame) {
  const core::Pose2 delta = odometry_.Inverse() * frame.odometry;
  if (delta.translation().norm() > options_.max_jump_m ||
      std::abs(delta.heading()) > options_.max_jump_rad) {
    Fail(
        fmt::format("reported odometry that jumped {:.2f} m and {:.0f}° between the last move "
                    "and CAPTURE, standing still: its odometry cannot be trusted",
                    delta.translation().norm(), core::RadToDeg(std::abs(delta.heading()))));
  }
  if (!last_frame_) return;
  if (frame.time_s < last_frame_->time_s) {
    Fail(
        fmt::format("sent a frame stamped {:.3f} s after one stamped {:.3f} s: its clock went "
                    "backwards, or its frames arrive out of order",
                    frame.time_s, last_frame_->time_s));
  }
  if (moved_since_frame_ && frame.time_s == last_frame_->time_s) {
    Fail(
        fmt::format("sent a frame stamped {:.3f} s, as the frame before it, though the robot "
                    "moved between them: a late frame, taken before the move",
                    frame.time_s));
  }
  if (!SameBytes(frame.image, last_frame_->image)) {
    identical_frames_ = 1;
  } else if (moved_since_frame_ && ++identical_frames_ >= options_.max_identical_frames) {
    Fail(
        fmt::format("sent the very same frame {} times in a row though the robot moved between "
                    "them: its camera is frozen",
                    identical_frames_));
  }
}

}  // namespace pirouette::robot
