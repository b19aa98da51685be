#include "pirouette/sim/velocity_robot.h"

#include <algorithm>
#include <cmath>

#include "pirouette/sim/disc_cast.h"
#include "pirouette/sim/seeded_random.h"

namespace pirouette::sim {
namespace {

// `current` moved toward `target` by at most `step`.
double Approach(double current, double target, double step) {
  return current + std::clamp(target - current, -step, step);
}

}  // namespace

VelocityRobot::VelocityRobot(const World& world, std::uint64_t seed,
                             const core::OdometryNoise& noise, const VelocityLimits& limits)
    : world_(world),
      noise_(noise),
      limits_(limits),
      rng_(seed),
      world_T_robot_(world.robot().start),
      odom_T_robot_(world.robot().start) {}

double VelocityRobot::Drive(double distance) {
  if (distance == 0.0) return 0.0;
  const Eigen::Vector2d u = (distance < 0.0 ? -1.0 : 1.0) * world_T_robot_.Direction();
  const double wanted = std::abs(distance);
  double travelled = wanted;
  const ContactResult contact =
      CastDisc(world_, world_T_robot_.translation(), u, world_.robot().radius);
  in_contact_ = contact.blocked <= wanted;
  if (in_contact_) travelled = std::min(contact.touch, wanted);
  const Eigen::Vector2d p = world_T_robot_.translation() + travelled * u;
  world_T_robot_ = core::Pose2(p.x(), p.y(), world_T_robot_.heading());
  return travelled;
}

// Both errors are drawn at the start of every motion whatever the noise, so
// that the stream of draws does not depend on it.
void VelocityRobot::Step(double linear_mps, double angular_rps, double dt) {
  const bool was_still = linear_ == 0.0 && angular_ == 0.0;
  const double v_target = std::clamp(linear_mps, -limits_.max_linear_mps, limits_.max_linear_mps);
  const double w_target =
      std::clamp(angular_rps, -limits_.max_angular_rps, limits_.max_angular_rps);
  linear_ = Approach(linear_, v_target, limits_.linear_accel_mps2 * dt);
  angular_ = Approach(angular_, w_target, limits_.angular_accel_rps2 * dt);
  if (was_still && (linear_ != 0.0 || angular_ != 0.0)) {
    translation_error_ = noise_.translation_bias + noise_.translation * StandardNormal(rng_);
    rotation_error_ = noise_.rotation_bias + noise_.rotation * StandardNormal(rng_);
  }
  time_s_ += dt;
  if (linear_ == 0.0 && angular_ == 0.0) {
    still_s_ += dt;
    return;
  }
  still_s_ = 0.0;
  // Half the turn, the drive, the other half: the arc's chord, to second order.
  const double half_turn = 0.5 * angular_ * dt;
  const double true_half_turn = half_turn * (1.0 + rotation_error_);
  world_T_robot_ = world_T_robot_ * core::Pose2(0.0, 0.0, true_half_turn);
  odom_T_robot_ = odom_T_robot_ * core::Pose2(0.0, 0.0, half_turn);
  if (linear_ != 0.0) {
    const double scale = 1.0 + translation_error_;  // true metres per encoder metre
    const double travelled = Drive(linear_ * dt * scale);
    const double measured = (linear_ < 0.0 ? -1.0 : 1.0) * travelled / std::abs(scale);
    odom_T_robot_ = odom_T_robot_ * core::Pose2(measured, 0.0, 0.0);
    if (in_contact_) linear_ = 0.0;  // the wheels stall against it
  }
  world_T_robot_ = world_T_robot_ * core::Pose2(0.0, 0.0, true_half_turn);
  odom_T_robot_ = odom_T_robot_ * core::Pose2(0.0, 0.0, half_turn);
}

}  // namespace pirouette::sim
