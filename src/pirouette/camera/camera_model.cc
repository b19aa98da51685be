#include "pirouette/camera/camera_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pirouette::camera {

CameraModel::CameraModel(std::string name, int width, int height, const Intrinsics& intrinsics,
                         const Distortion& distortion, const Mount& mount,
                         const Vignetting& vignetting)
    : name_(std::move(name)),
      width_(width),
      height_(height),
      intrinsics_(intrinsics),
      distortion_(distortion),
      mount_(mount),
      vignetting_(vignetting) {
  if (width <= 0 || height <= 0 || !(intrinsics.fx > 0) || !(intrinsics.fy > 0) ||
      !(mount.height_m > 0) || !std::isfinite(intrinsics.fx) || !std::isfinite(intrinsics.fy) ||
      !std::isfinite(intrinsics.cx) || !std::isfinite(intrinsics.cy) ||
      !std::isfinite(mount.height_m) || !std::isfinite(mount.forward_m)) {
    throw std::invalid_argument(
        "CameraModel: size, focal lengths and mount height must be finite and > 0");
  }
  if (!(std::abs(mount.tilt_rad) < std::numbers::pi / 2)) {
    throw std::invalid_argument(
        "CameraModel: the tilt must lie strictly between -90 and 90 degrees");
  }
  for (const double k : {distortion.k1, distortion.k2, distortion.p1, distortion.p2, distortion.k3,
                         distortion.k4, distortion.k5, distortion.k6}) {
    if (!std::isfinite(k)) throw std::invalid_argument("CameraModel: distortion must be finite");
  }
  if (Distortion::FromCoefficients(distortion.model, distortion.Coefficients()) != distortion) {
    throw std::invalid_argument(
        "CameraModel: a coefficient the distortion model does not use is set");
  }
  for (const double k : vignetting.k) {
    if (!(k >= 0.0) || !std::isfinite(k)) {
      throw std::invalid_argument("CameraModel: vignetting k must be finite and >= 0");
    }
  }
  double r2 = 0.0;
  for (const double u : {0.0, static_cast<double>(width - 1)}) {
    for (const double v : {0.0, static_cast<double>(height - 1)}) {
      const double du = u - intrinsics.cx;
      const double dv = v - intrinsics.cy;
      r2 = std::max(r2, du * du + dv * dv);
    }
  }
  r_max_squared_ = std::max(r2, 1e-12);
}

Eigen::Vector2d CameraModel::Distort(const Eigen::Vector2d& undistorted) const {
  return distortion_.Distort(undistorted);
}

Eigen::Vector2d CameraModel::Undistort(const Eigen::Vector2d& distorted) const {
  return distortion_.Undistort(distorted).value_or(distorted);
}

std::optional<Eigen::Vector2d> CameraModel::Project(const Eigen::Vector3d& p_camera) const {
  if (!(p_camera.z() > 0.0)) return std::nullopt;
  const Eigen::Vector2d distorted = Distort(p_camera.head<2>() / p_camera.z());
  return Eigen::Vector2d(intrinsics_.fx * distorted.x() + intrinsics_.cx,
                         intrinsics_.fy * distorted.y() + intrinsics_.cy);
}

Eigen::Vector3d CameraModel::Backproject(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d distorted((pixel.x() - intrinsics_.cx) / intrinsics_.fx,
                                  (pixel.y() - intrinsics_.cy) / intrinsics_.fy);
  if (const std::optional<Eigen::Vector3d> ray = distortion_.Ray(distorted)) return *ray;
  const Eigen::Vector2d undistorted = Undistort(distorted);
  return Eigen::Vector3d(undistorted.x(), undistorted.y(), 1.0).normalized();
}

std::optional<Eigen::Vector3d> CameraModel::SeenRay(const Eigen::Vector2d& pixel) const {
  return distortion_.Ray({(pixel.x() - intrinsics_.cx) / intrinsics_.fx,
                          (pixel.y() - intrinsics_.cy) / intrinsics_.fy});
}

Eigen::Isometry3d CameraModel::robot_T_camera() const {
  // Columns: the camera's x (right), y (down), z (optical axis) in the robot
  // frame (x forward, y left, z up), for an axis pitched down by the tilt.
  const double c = std::cos(mount_.tilt_rad);
  const double s = std::sin(mount_.tilt_rad);
  Eigen::Matrix3d rotation;
  rotation.col(0) = Eigen::Vector3d(0.0, -1.0, 0.0);
  rotation.col(1) = Eigen::Vector3d(-s, 0.0, -c);
  rotation.col(2) = Eigen::Vector3d(c, 0.0, -s);
  Eigen::Isometry3d robot_T_camera = Eigen::Isometry3d::Identity();
  robot_T_camera.linear() = rotation;
  robot_T_camera.translation() = Eigen::Vector3d(mount_.forward_m, 0.0, mount_.height_m);
  return robot_T_camera;
}

std::optional<Eigen::Vector2d> CameraModel::FloorPoint(const Eigen::Vector2d& pixel) const {
  const Eigen::Isometry3d robot_T_camera = this->robot_T_camera();
  const std::optional<Eigen::Vector3d> ray = SeenRay(pixel);
  if (!ray) return std::nullopt;
  const Eigen::Vector3d ray_robot = robot_T_camera.linear() * *ray;
  // Rays that go down less steeply than this never meet the floor within any
  // useful range (about 10 km from 0.1 m); they count as above the horizon.
  if (!(ray_robot.z() < -1e-5)) return std::nullopt;
  const Eigen::Vector3d origin = robot_T_camera.translation();
  const double t = -origin.z() / ray_robot.z();
  return (origin + t * ray_robot).head<2>();
}

double CameraModel::VignettingGain(int channel, const Eigen::Vector2d& pixel) const {
  assert(channel >= 0 && channel < 3);
  const double du = pixel.x() - intrinsics_.cx;
  const double dv = pixel.y() - intrinsics_.cy;
  const double rho2 = (du * du + dv * dv) / r_max_squared_;
  return 1.0 / (1.0 + vignetting_.k[static_cast<std::size_t>(channel)] * rho2);
}

}  // namespace pirouette::camera
