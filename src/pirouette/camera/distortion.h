#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace pirouette::camera {

// OpenCV's / ROS's `plumb_bob` lens distortion (Brown–Conrady), on normalised
// image coordinates (x/z, y/z): radial k1, k2, k3 and tangential p1, p2.
struct PlumbBob {
  double k1 = 0.0;
  double k2 = 0.0;
  double p1 = 0.0;
  double p2 = 0.0;
  double k3 = 0.0;
};

// A lens distortion model of ROS's camera_info (sensor_msgs/distortion_models.hpp)
// with its coefficients, named as OpenCV names them:
//  - kPlumbBob: k1 k2 p1 p2 k3, OpenCV's default model (cv::projectPoints).
//  - kRationalPolynomial: k1 k2 p1 p2 k3 k4 k5 k6, OpenCV's CALIB_RATIONAL_MODEL:
//      radial = (1 + k1 r² + k2 r⁴ + k3 r⁶) / (1 + k4 r² + k5 r⁴ + k6 r⁶),
//      tangential as plumb_bob.
//  - kEquidistant: k1 k2 k3 k4 of cv::fisheye (p1 p2 k5 k6 stay 0):
//      θ = atan(r), θd = θ (1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸),
//      distorted = (θd / r) (x, y).
// r² = x² + y² of the undistorted normalised point (x, y). Coefficients a
// model does not use are 0. Sources: OpenCV's "Camera Calibration and 3D
// Reconstruction" and "Fisheye camera model" reference pages.
struct Distortion {
  enum class Model { kPlumbBob, kRationalPolynomial, kEquidistant };

  Model model = Model::kPlumbBob;
  double k1 = 0.0;
  double k2 = 0.0;
  double p1 = 0.0;
  double p2 = 0.0;
  double k3 = 0.0;
  double k4 = 0.0;
  double k5 = 0.0;
  double k6 = 0.0;

  Distortion() = default;
  // Every plumb_bob is a Distortion: the widening keeps the callers that
  // hold a PlumbBob working unchanged.
  Distortion(const PlumbBob& d)  // NOLINT(google-explicit-constructor)
      : k1(d.k1), k2(d.k2), p1(d.p1), p2(d.p2), k3(d.k3) {}
  // A plumb_bob from its coefficients, so that `{k1, k2, p1, p2, k3}` reads as one.
  Distortion(double k1, double k2, double p1, double p2, double k3)
      : k1(k1), k2(k2), p1(p1), p2(p2), k3(k3) {}

  // A model from its coefficients in ROS's order (camera_info's D, the order
  // above); nullopt when their count does not fit the model. plumb_bob also
  // takes 4 (k3 = 0).
  static std::optional<Distortion> FromCoefficients(Model model,
                                                    std::span<const double> coefficients);
  // The coefficients in ROS's order, as many as the model has (5, 8 or 4).
  std::vector<double> Coefficients() const;

  // Normalised undistorted → normalised distorted coordinates.
  Eigen::Vector2d Distort(const Eigen::Vector2d& undistorted) const;
  // The inverse of Distort: the normalised undistorted point, or nullopt
  // where no point in front of the camera is distorted to `distorted` (beyond
  // a fisheye's image circle, where θd exceeds the largest value of the
  // model's increasing part on θ < 90°, or where the rational model has no
  // inverse near the point). plumb_bob always answers, by Newton's method.
  std::optional<Eigen::Vector2d> Undistort(const Eigen::Vector2d& distorted) const;
  // The unit ray (camera frame, z along the axis) whose image is the
  // normalised distorted point, or nullopt as for Undistort. For a fisheye
  // this stays exact as θ nears 90°, where Undistort's x/z grows without bound.
  std::optional<Eigen::Vector3d> Ray(const Eigen::Vector2d& distorted) const;

  bool operator==(const Distortion&) const = default;
};

// ROS's name of a model ("plumb_bob", "rational_polynomial", "equidistant").
std::string_view ModelName(Distortion::Model model);
// The model ROS names `name`; nullopt for any other name.
std::optional<Distortion::Model> ModelNamed(std::string_view name);

}  // namespace pirouette::camera
