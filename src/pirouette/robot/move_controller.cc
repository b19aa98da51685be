#include "pirouette/robot/move_controller.h"

#include <algorithm>
#include <cmath>

#include "pirouette/core/angle.h"

namespace pirouette::robot {
namespace {

// The speed of a trapezoidal profile `elapsed` seconds into a move with
// `remaining` left to go (both ≥ 0).
double ProfileSpeed(double elapsed, double remaining, double cruise, double accel, double minimum) {
  const double ramp_up = accel * elapsed;
  const double brake = std::sqrt(2.0 * accel * remaining);
  return std::max(minimum, std::min({cruise, ramp_up, brake}));
}

}  // namespace

MoveController::MoveController(const core::Move& move, const core::Pose2& start,
                               double start_time_s, const MotionLimits& limits)
    : move_(move), start_(start), start_time_s_(start_time_s), limits_(limits), last_(start) {}

bool MoveController::reached() const {
  // A move smaller than twice the tolerance is still made, to half its size
  // at worst: a caller that asks for 2 mm wants motion, not a no-op it would
  // ask for again and again.
  const double tolerance =
      std::min(move_.kind == core::Move::Kind::kTurn ? limits_.angle_tolerance_rad
                                                     : limits_.distance_tolerance_m,
               0.5 * std::abs(move_.amount));
  const double sign = move_.amount < 0.0 ? -1.0 : 1.0;
  return sign * (move_.amount - progress_) <= tolerance;
}

Velocity MoveController::Update(const core::Pose2& odometry, double time_s) {
  const double sign = move_.amount < 0.0 ? -1.0 : 1.0;
  if (move_.kind == core::Move::Kind::kTurn) {
    progress_ += core::NormalizeAngle(odometry.heading() - last_.heading());
  } else {
    progress_ = (odometry.translation() - start_.translation()).dot(start_.Direction());
  }
  last_ = odometry;
  if (reached()) return {};
  const double remaining = sign * (move_.amount - progress_);
  const double elapsed = std::max(0.0, time_s - start_time_s_);
  if (move_.kind == core::Move::Kind::kTurn) {
    return {0.0, sign * ProfileSpeed(elapsed, remaining, limits_.max_angular_rps,
                                     limits_.angular_accel_rps2, limits_.min_angular_rps)};
  }
  return {sign * ProfileSpeed(elapsed, remaining, limits_.max_linear_mps, limits_.linear_accel_mps2,
                              limits_.min_linear_mps),
          0.0};
}

}  // namespace pirouette::robot
