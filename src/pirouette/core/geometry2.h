#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace pirouette::core {

// The z of the 3D cross product of two plane vectors: positive when b turns
// counter-clockwise from a.
inline double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The distance from p to the closed segment ab (to a when a == b).
inline double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double s =
      length_squared > 0.0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return (a + s * ab - p).norm();
}

}  // namespace pirouette::core
