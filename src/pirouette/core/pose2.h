#pragma once

#include <Eigen/Core>
#include <cmath>

#include "pirouette/core/angle.h"

namespace pirouette::core {

// A rigid transform of the plane: `a_T_b` maps points given in frame b into
// frame a. For the robot, `world_T_robot` is its pose: position of its centre
// of rotation and heading (radians, counter-clockwise from the world's +x).
class Pose2 {
 public:
  Pose2() = default;
  Pose2(double x, double y, double heading_rad)
      : translation_(x, y), heading_(NormalizeAngle(heading_rad)) {}

  double x() const { return translation_.x(); }
  double y() const { return translation_.y(); }
  double heading() const { return heading_; }
  const Eigen::Vector2d& translation() const { return translation_; }

  // The unit vector of the heading.
  Eigen::Vector2d Direction() const { return {std::cos(heading_), std::sin(heading_)}; }

  Eigen::Vector2d operator*(const Eigen::Vector2d& p_b) const {
    const double c = std::cos(heading_);
    const double s = std::sin(heading_);
    return {translation_.x() + c * p_b.x() - s * p_b.y(),
            translation_.y() + s * p_b.x() + c * p_b.y()};
  }

  Pose2 operator*(const Pose2& b_T_c) const {
    const Eigen::Vector2d t = (*this) * b_T_c.translation_;
    return {t.x(), t.y(), heading_ + b_T_c.heading_};
  }

  Pose2 Inverse() const {
    const double c = std::cos(heading_);
    const double s = std::sin(heading_);
    return {-c * translation_.x() - s * translation_.y(),
            s * translation_.x() - c * translation_.y(), -heading_};
  }

 private:
  Eigen::Vector2d translation_ = Eigen::Vector2d::Zero();
  double heading_ = 0.0;
};

}  // namespace pirouette::core
