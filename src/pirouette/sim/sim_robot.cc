#include "pirouette/sim/sim_robot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "pirouette/sim/disc_cast.h"
#include "pirouette/sim/seeded_random.h"

namespace pirouette::sim {
namespace {

// The simulated robot's speeds (for the frames' time stamps only).
constexpr double kDriveSpeed = 0.1;                    // metres a second
constexpr double kTurnSpeed = std::numbers::pi / 2.0;  // radians a second (90°/s)
constexpr double kCaptureTime = 0.05;                  // seconds a frame

}  // namespace

SimRobot::SimRobot(const World& world, std::uint64_t seed, View view)
    : SimRobot(world, seed, std::move(view), world.robot().odometry_noise) {}

SimRobot::SimRobot(const World& world, std::uint64_t seed, View view,
                   const core::OdometryNoise& noise)
    : world_(world),
      noise_(noise),
      view_(std::move(view)),
      rng_(seed),
      world_T_robot_(world.robot().start),
      // The odometry frame is the world frame at the start: odometry and
      // truth agree until the robot first moves.
      odom_T_robot_(world.robot().start) {}

// One standard normal is drawn per move whatever the noise, so that the
// stream of draws, and so the trajectory for a seed, does not depend on it.
core::MoveOutcome SimRobot::Execute(const core::Move& move) {
  core::MoveOutcome outcome;
  outcome.requested = move;
  if (move.kind == core::Move::Kind::kTurn) {
    const double epsilon = noise_.rotation_bias + noise_.rotation * StandardNormal(rng_);
    const double true_angle = move.amount * (1.0 + epsilon);
    world_T_robot_ =
        core::Pose2(world_T_robot_.x(), world_T_robot_.y(), world_T_robot_.heading() + true_angle);
    odom_T_robot_ =
        core::Pose2(odom_T_robot_.x(), odom_T_robot_.y(), odom_T_robot_.heading() + move.amount);
    outcome.achieved = move.amount;
    time_s_ += std::abs(true_angle) / kTurnSpeed;
  } else {
    const double epsilon = noise_.translation_bias + noise_.translation * StandardNormal(rng_);
    const double scale = 1.0 + epsilon;  // true distance per encoder distance
    const double true_signed = move.amount * scale;
    const Eigen::Vector2d u = (true_signed < 0.0 ? -1.0 : 1.0) * world_T_robot_.Direction();
    const double wanted = std::abs(true_signed);
    double travelled = wanted;
    if (wanted > 0.0) {
      const ContactResult contact =
          CastDisc(world_, world_T_robot_.translation(), u, world_.robot().radius);
      if (contact.blocked <= wanted) {
        travelled = std::min(contact.touch, wanted);
        outcome.stopped_at_contact = true;
      }
    }
    const Eigen::Vector2d p = world_T_robot_.translation() + travelled * u;
    world_T_robot_ = core::Pose2(p.x(), p.y(), world_T_robot_.heading());
    // What the encoders measure: the true distance over the scale, in the
    // sign of the command.
    const double measured = (move.amount < 0.0 ? -1.0 : 1.0) * travelled / std::abs(scale);
    outcome.achieved = outcome.stopped_at_contact ? measured : move.amount;
    odom_T_robot_ = odom_T_robot_ * core::Pose2(outcome.achieved, 0.0, 0.0);
    time_s_ += travelled / kDriveSpeed;
  }
  outcome.odometry = odom_T_robot_;
  return outcome;
}

// The frame is stamped at the moment it is taken; taking it lasts kCaptureTime.
// A null view gives empty images.
robot::Frame SimRobot::Capture() {
  robot::Frame frame;
  if (view_) frame.image = view_(world_T_robot_);
  frame.odometry = odom_T_robot_;
  frame.time_s = time_s_;
  time_s_ += kCaptureTime;
  return frame;
}

}  // namespace pirouette::sim
