#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>

#include "pirouette/camera/distortion.h"

namespace pirouette::camera {

// Pinhole intrinsics in pixels (the camera_matrix of ROS's camera_info, no skew).
// The centre of pixel (u, v) has the image coordinates (u, v), as in OpenCV.
struct Intrinsics {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
};

// Where the camera sits on the robot. The robot frame is x forward, y left,
// z up, with its origin at the centre of rotation on the floor. The optical
// centre is at (forward_m, 0, height_m); the optical axis points forward and
// is pitched down by tilt_rad below the horizontal; image rows run downward.
struct Mount {
  double height_m = 0.0;
  double tilt_rad = 0.0;
  double forward_m = 0.0;
};

// Per channel R, G, B: the lens passes 1 / (1 + k·(r/r_max)²) of the light,
// r being the distance from the principal point and r_max its distance to the
// farthest image corner (a corner pixel's centre). SPEC.md, camera file.
struct Vignetting {
  std::array<double, 3> k = {0.0, 0.0, 0.0};
};

// The camera model: intrinsics, distortion (plumb_bob, rational_polynomial or
// equidistant), vignetting and mount.
// Immutable; the constructor checks its values (a bad value is a bug here:
// the file loader refuses bad input with a message before it gets here).
//
// OpenCV implements the same distortions (cv::projectPoints,
// cv::fisheye::projectPoints), but DESIGN.md
// keeps the camera layer free of OpenCV; tests check this code against it.
class CameraModel {
 public:
  CameraModel(std::string name, int width, int height, const Intrinsics& intrinsics,
              const Distortion& distortion, const Mount& mount, const Vignetting& vignetting);

  const std::string& name() const { return name_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const Intrinsics& intrinsics() const { return intrinsics_; }
  const Distortion& distortion() const { return distortion_; }
  const Mount& mount() const { return mount_; }
  const Vignetting& vignetting() const { return vignetting_; }

  // Normalised undistorted → normalised distorted coordinates (the distortion's model).
  Eigen::Vector2d Distort(const Eigen::Vector2d& undistorted) const;
  // The inverse of Distort, to 1e-12; exact within the region where the model
  // is monotonic (every pixel of a sane calibration). Where no point in front
  // of the camera is distorted to `distorted` (Distortion::Undistort's
  // nullopt: beyond a fisheye's image circle), `distorted` itself.
  Eigen::Vector2d Undistort(const Eigen::Vector2d& distorted) const;

  // The pixel where a point in the camera frame (OpenCV: x right, y down,
  // z along the axis) is seen, with distortion; nullopt when z <= 0.
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& p_camera) const;
  // The unit ray, in the camera frame, of the light that reaches `pixel`
  // (for a pixel that sees nothing, as SeenRay's nullopt, the ray of Undistort's answer).
  Eigen::Vector3d Backproject(const Eigen::Vector2d& pixel) const;
  // The same, or nullopt where no light reaches `pixel` (beyond a fisheye's
  // image circle). A fisheye's rays may lie up to 90° off the axis.
  std::optional<Eigen::Vector3d> SeenRay(const Eigen::Vector2d& pixel) const;

  // The camera's pose in the robot frame (x forward, y left, z up).
  Eigen::Isometry3d robot_T_camera() const;

  // The point on the floor (z = 0), in the robot frame, seen at `pixel`;
  // nullopt where the pixel's ray does not go down to the floor.
  std::optional<Eigen::Vector2d> FloorPoint(const Eigen::Vector2d& pixel) const;

  // The fraction of light passed at `pixel` for channel c (0 R, 1 G, 2 B).
  double VignettingGain(int channel, const Eigen::Vector2d& pixel) const;
  // r_max² of the vignetting model: the squared distance, in pixels, from the
  // principal point to the farthest corner pixel's centre.
  double vignetting_r_max_squared() const { return r_max_squared_; }

 private:
  std::string name_;
  int width_;
  int height_;
  Intrinsics intrinsics_;
  Distortion distortion_;
  Mount mount_;
  Vignetting vignetting_;
  double r_max_squared_;  // squared distance from the principal point to the farthest corner
};

}  // namespace pirouette::camera
