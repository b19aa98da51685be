#include "pirouette/camera/inverse_perspective_map.h"

#include <algorithm>
#include <cassert>

namespace pirouette::camera {

InversePerspectiveMap::InversePerspectiveMap(const CameraModel& camera)
    : width_(camera.width()), height_(camera.height()) {
  const std::size_t size = static_cast<std::size_t>(width_) * height_;
  floor_points_.assign(size, Eigen::Vector2f::Zero());
  sees_floor_.assign(size, 0);
  for (int v = 0; v < height_; ++v) {
    for (int u = 0; u < width_; ++u) {
      const std::optional<Eigen::Vector2d> p_robot = camera.FloorPoint(Eigen::Vector2d(u, v));
      if (!p_robot) continue;
      floor_points_[Index(u, v)] = p_robot->cast<float>();
      sees_floor_[Index(u, v)] = 1;
    }
  }
}

std::optional<Eigen::Vector2f> InversePerspectiveMap::At(int u, int v) const {
  const std::size_t i = Index(u, v);
  if (sees_floor_[i] == 0) return std::nullopt;
  return floor_points_[i];
}

std::size_t InversePerspectiveMap::Index(int u, int v) const {
  assert(u >= 0 && u < width_ && v >= 0 && v < height_);
  return static_cast<std::size_t>(v) * width_ + u;
}

double NearRange(const InversePerspectiveMap& ipm) {
  double near = 0.0;
  const int v = ipm.height() - 1;
  for (int u = 0; u < ipm.width(); ++u) {
    if (const auto p = ipm.At(u, v)) near = std::max(near, static_cast<double>(p->norm()));
  }
  return near;
}

}  // namespace pirouette::camera
