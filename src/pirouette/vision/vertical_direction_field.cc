#include "pirouette/vision/vertical_direction_field.h"

#include <algorithm>
#include <cmath>

namespace pirouette::vision {

VerticalDirectionField::VerticalDirectionField(const camera::CameraModel& camera, int scale)
    : direction_(camera.height() / std::max(scale, 1), camera.width() / std::max(scale, 1)) {
  CV_Assert(scale >= 1 && !direction_.empty());
  const double centre = 0.5 * (scale - 1);
  const Eigen::Isometry3d robot_T_camera = camera.robot_T_camera();
  const Eigen::Isometry3d camera_T_robot = robot_T_camera.inverse();
  constexpr double kHalfStep = 0.001;  // metres along the vertical line
  for (int v = 0; v < direction_.rows; ++v) {
    for (int u = 0; u < direction_.cols; ++u) {
      const Eigen::Vector3d ray_camera =
          camera.Backproject(Eigen::Vector2d(u * scale + centre, v * scale + centre));
      const Eigen::Vector3d p_robot = robot_T_camera * ray_camera;  // 1 m from the optical centre
      const auto below =
          camera.Project(camera_T_robot * (p_robot - kHalfStep * Eigen::Vector3d::UnitZ()));
      const auto above =
          camera.Project(camera_T_robot * (p_robot + kHalfStep * Eigen::Vector3d::UnitZ()));
      cv::Vec2f up(0.0f, -1.0f);
      if (below && above) {
        const Eigen::Vector2d d = *above - *below;
        if (d.norm() > 1e-9) {
          const Eigen::Vector2d unit = d.normalized();
          up = cv::Vec2f(static_cast<float>(unit.x()), static_cast<float>(unit.y()));
        }
      }
      direction_(v, u) = up;
    }
  }
}

VerticalDirectionField::VerticalDirectionField(int width, int height)
    : direction_(height, width, cv::Vec2f(0.0f, -1.0f)) {}

}  // namespace pirouette::vision
